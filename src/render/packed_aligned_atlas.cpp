// The packed atlas of a fully aligned series: four time-steps per RGBA16 texel.
#include "tstyles/render/packed_aligned_atlas.h"

#include <algorithm>
#include <variant>

#include "tstyles/core/errors.h"
#include "tstyles/data/series_summary.h"
#include "tstyles/render/bindings.h"
#include "tstyles/render/density_texels.h"

namespace tstyles {
namespace {

bool isEvenRectilinear(const TimeStep& step) {
    const auto* grid = std::get_if<RectilinearGrid>(&step.grid);
    return grid && !grid->isUneven(0) && !grid->isUneven(1) && !grid->isUneven(2);
}

}  // namespace

bool suitsPackedAtlas(const Series& series) {
    // The packed atlas is RGBA16: only for 16-bit storage, so that packed and unpacked agree.
    return series.size() >= 2 && series.precision == DensityPrecision::Bits16 && isFullyAligned(series) &&
           std::all_of(series.steps.begin(), series.steps.end(), isEvenRectilinear) && !series.hasMasks() &&
           !hasMissingValues(series);
}

std::vector<std::uint16_t> packedGroupTexels(const Series& series, std::size_t group) {
    const std::size_t voxels = series.steps.front().density.size();
    std::vector<std::uint16_t> texels(voxels * kTimeStepsPerTexel, 0);
    for (int channel = 0; channel < kTimeStepsPerTexel; ++channel) {
        const std::size_t step = group * kTimeStepsPerTexel + std::size_t(channel);
        if (step >= series.size()) break;
        const std::vector<std::uint16_t> densities = densityTexels(series.steps[step], false);
        for (std::size_t voxel = 0; voxel < voxels; ++voxel)
            texels[voxel * kTimeStepsPerTexel + std::size_t(channel)] = densities[voxel];
    }
    return texels;
}

std::vector<std::uint8_t> unionOfVisibilities(const std::vector<std::vector<std::uint8_t>>& visibilities) {
    std::vector<std::uint8_t> result(visibilities.empty() ? 0 : visibilities.front().size(), 0);
    for (const auto& visibility : visibilities)
        for (std::size_t brick = 0; brick < result.size(); ++brick)
            result[brick] = std::max(result[brick], visibility[brick]);
    return result;
}

PackedAlignedAtlas::PackedAlignedAtlas(const Series& series, glm::ivec3 brickCounts, int maxTextureSize)
    : brickCounts_(brickCounts),
      atlas_(Texture::create(GL_TEXTURE_3D)),
      occupancy_(Texture::create(GL_TEXTURE_3D)),
      groupOrigins_(Buffer::create()) {
    const std::size_t groups = (series.size() + kTimeStepsPerTexel - 1) / kTimeStepsPerTexel;
    const glm::ivec3 dims = series.steps.front().dims();
    layout_ = planAtlas(std::vector<glm::ivec3>(groups, dims), maxTextureSize);

    glTextureStorage3D(atlas_.id(), 1, GL_RGBA16, layout_.size.x, layout_.size.y, layout_.size.z);
    atlas_.setFilter(GL_LINEAR, GL_LINEAR);
    atlas_.setClampToEdge();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    std::vector<glm::vec4> origins;
    for (std::size_t group = 0; group < groups; ++group) {
        const glm::ivec3 origin = layout_.brickOrigins[group];
        const std::vector<std::uint16_t> texels = packedGroupTexels(series, group);
        glTextureSubImage3D(atlas_.id(), 0, origin.x, origin.y, origin.z, dims.x, dims.y, dims.z, GL_RGBA,
                            GL_UNSIGNED_SHORT, texels.data());
        origins.push_back(glm::vec4(glm::vec3(origin), 0.0f));
    }
    groupOrigins_.setData(std::as_bytes(std::span(origins)), GL_STATIC_DRAW);

    glTextureStorage3D(occupancy_.id(), 1, GL_R8, brickCounts.x, brickCounts.y, brickCounts.z);
    occupancy_.setFilter(GL_NEAREST, GL_NEAREST);
    occupancy_.setClampToEdge();
}

std::size_t PackedAlignedAtlas::textureBytes() const {
    return layout_.texelCount() * 8 + std::size_t(brickCounts_.x) * std::size_t(brickCounts_.y) *
                                          std::size_t(brickCounts_.z);
}

void PackedAlignedAtlas::updateOccupancy(const std::vector<std::uint8_t>& unionVisibility) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage3D(occupancy_.id(), 0, 0, 0, 0, brickCounts_.x, brickCounts_.y, brickCounts_.z, GL_RED,
                        GL_UNSIGNED_BYTE, unionVisibility.data());
}

void PackedAlignedAtlas::bind() const {
    atlas_.bindToUnit(binding::kPackedAtlasUnit);
    occupancy_.bindToUnit(binding::kPackedOccupancyUnit);
    groupOrigins_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::kPackedGroupBuffer);
}

}  // namespace tstyles
