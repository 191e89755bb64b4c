// The gradient atlas' lifetime in a renderer: when it is made, and whether a frame reads it.
#include "tstyles/render/precomputed_gradients.h"

#include <algorithm>
#include <cstdint>

namespace tstyles {

PrecomputedGradients::PrecomputedGradients(const ShaderLibrary& shaders, bool cpuRasterizer)
    : shaders_(shaders), cpuRasterizer_(cpuRasterizer) {}

void PrecomputedGradients::startSeries(const std::optional<GpuMemoryLimits>& limits) {
    atlas_.reset();
    limits_ = limits;
    seriesDrawnStyled_ = false;
    atlasTried_ = false;
}

bool PrecomputedGradients::fits(const GpuSeries& series) const {
    if (cpuRasterizer_ && series.layout().texelCount() > kCpuRasterizerGradientTexels) return false;
    if (!limits_) return true;
    // What the budget leaves after the series, and no more than the driver's largest texture.
    const std::uint64_t used = series.textureBytes();
    std::uint64_t left = limits_->budgetBytes > used ? limits_->budgetBytes - used : 0;
    if (limits_->largestTextureBytes) left = std::min(left, *limits_->largestTextureBytes);
    return GradientAtlas::bytesFor(series.layout()) <= left;
}

bool PrecomputedGradients::useFor(const GpuSeries& series, bool styled, std::optional<bool> forced) {
    if (!styled || !forced.value_or(true) || !GradientAtlas::suits(series)) return false;
    if (!forced && !seriesDrawnStyled_) {
        seriesDrawnStyled_ = true;
        return false;
    }
    if (!atlasTried_) {
        atlasTried_ = true;
        if (fits(series)) {
            if (!program_) program_ = GradientAtlas::buildProgram(shaders_);
            atlas_ = GradientAtlas::compute(*program_, series);
        }
    }
    if (!atlas_) return false;
    atlas_->bind();
    return true;
}

}  // namespace tstyles
