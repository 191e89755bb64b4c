// When a renderer's styles read precomputed gradients, and the gradient atlas they read
// (gradient_atlas.h): made at a series' second styled frame (a one-frame `render` would spend more
// on it than it saves), only where the series suits, where the GPU memory budget holds it after the
// series, and on a CPU rasterizer only for series of at most kCpuRasterizerGradientTexels.
#pragma once

#include <cstddef>
#include <optional>

#include "tstyles/gl/program.h"
#include "tstyles/render/gpu_memory_budget.h"
#include "tstyles/render/gpu_series.h"
#include "tstyles/render/gradient_atlas.h"

namespace tstyles {

// On a CPU rasterizer the gradient atlas takes about 30 ns a texel to make (llvmpipe, 2 cores: 2.8 s
// for 87 M texels, 0.14 s for the bundled super-ellipsoid's 2.6 M), so a series of 16 M texels
// costs about 0.5 s once, a few styled 512² frames' worth; larger series keep the six fetches
// there (docs/performance.md). A GPU makes it in milliseconds.
inline constexpr std::size_t kCpuRasterizerGradientTexels = std::size_t(16) << 20;

class PrecomputedGradients {
public:
    PrecomputedGradients(const ShaderLibrary& shaders, bool cpuRasterizer);

    // A new series is about to be uploaded: the old atlas is freed. `limits`: the budget it will be
    // uploaded within (none: no budget); the atlas may take what the series leaves of it.
    void startSeries(const std::optional<GpuMemoryLimits>& limits);
    // Whether a frame of `series` reads the gradient atlas, which is then bound; makes it when one
    // first should. `forced`: FrameOptions::precomputedGradients.
    bool useFor(const GpuSeries& series, bool styled, std::optional<bool> forced);
    std::size_t textureBytes() const { return atlas_ ? atlas_->textureBytes() : 0; }

private:
    bool fits(const GpuSeries& series) const;

    const ShaderLibrary& shaders_;
    bool cpuRasterizer_;
    std::optional<Program> program_;  // built at the first atlas
    std::optional<GpuMemoryLimits> limits_;
    bool seriesDrawnStyled_ = false;  // a styled frame of the series was drawn (with six-fetch gradients)
    bool atlasTried_ = false;
    std::optional<GradientAtlas> atlas_;
};

}  // namespace tstyles
