// The packed atlas of a fully aligned series: four time-steps per RGBA16 texel, and their
// validities in a second one when values are missing.
#include "tstyles/render/packed_aligned_atlas.h"

#include <algorithm>
#include <variant>

#include "tstyles/core/errors.h"
#include "tstyles/data/series_summary.h"
#include "tstyles/render/brick_occupancy.h"
#include "tstyles/render/shader_contract.h"
#include "tstyles/render/density_texels.h"
#include "tstyles/render/empty_brick_reach.h"

namespace tstyles {
namespace {

bool isRectilinear(const TimeStep& step) {
    return std::holds_alternative<RectilinearGrid>(step.grid);
}

// One channel per time-step of the group: value(step, voxel) for its voxels, 0 past the last step.
template <typename ValueOfVoxel>
std::vector<std::uint16_t> interleaveGroup(const Series& series, std::size_t group, ValueOfVoxel valueOf) {
    const std::size_t voxels = series.steps.front().density.size();
    std::vector<std::uint16_t> texels(voxels * kTimeStepsPerTexel, 0);
    for (int channel = 0; channel < kTimeStepsPerTexel; ++channel) {
        const std::size_t step = group * kTimeStepsPerTexel + std::size_t(channel);
        if (step >= series.size()) break;
        valueOf(series.steps[step], [&](std::size_t voxel, std::uint16_t value) {
            texels[voxel * kTimeStepsPerTexel + std::size_t(channel)] = value;
        });
    }
    return texels;
}

}  // namespace

bool suitsPackedAtlas(const Series& series) {
    // The packed atlas is RGBA16: only for 16-bit storage, so that packed and unpacked agree.
    return series.precision == DensityPrecision::Bits16 && suitsPackedAtlasAt16Bits(series);
}

bool suitsPackedAtlasAt16Bits(const Series& series) {
    return series.size() >= 2 && isFullyAligned(series) &&
           std::all_of(series.steps.begin(), series.steps.end(), isRectilinear) && !series.hasMasks();
}

std::vector<std::uint16_t> packedGroupTexels(const Series& series, std::size_t group, bool withValidity) {
    return interleaveGroup(series, group, [withValidity](const TimeStep& step, auto store) {
        // With validity, densityTexels gives (premultiplied density, validity) pairs.
        const std::vector<std::uint16_t> densities = densityTexels(step, withValidity);
        const std::size_t stride = withValidity ? 2 : 1;
        for (std::size_t voxel = 0; voxel < step.density.size(); ++voxel) store(voxel, densities[voxel * stride]);
    });
}

std::vector<std::uint16_t> validityTexels(const TimeStep& step) {
    std::vector<std::uint16_t> texels(step.density.size());
    std::transform(step.density.begin(), step.density.end(), texels.begin(),
                   [](float density) { return isMissing(density) ? std::uint16_t(0) : std::uint16_t(65535); });
    return texels;
}

std::vector<std::uint16_t> packedGroupValidities(const Series& series, std::size_t group) {
    return interleaveGroup(series, group, [](const TimeStep& step, auto store) {
        const std::vector<std::uint16_t> validities = validityTexels(step);
        for (std::size_t voxel = 0; voxel < validities.size(); ++voxel) store(voxel, validities[voxel]);
    });
}

PackedValidity packedValidityOf(const Series& series) {
    if (!hasMissingValues(series)) return PackedValidity::None;
    const std::vector<std::uint16_t> first = validityTexels(series.steps.front());
    const bool shared = std::all_of(series.steps.begin() + 1, series.steps.end(),
                                    [&first](const TimeStep& step) { return validityTexels(step) == first; });
    return shared ? PackedValidity::Shared : PackedValidity::PerGroup;
}

std::vector<std::uint8_t> unionOfVisibilities(const std::vector<std::vector<std::uint8_t>>& visibilities) {
    std::vector<std::uint8_t> result(visibilities.empty() ? 0 : visibilities.front().size(), 0);
    for (const auto& visibility : visibilities)
        for (std::size_t brick = 0; brick < result.size(); ++brick)
            result[brick] = std::max(result[brick], visibility[brick]);
    return result;
}

std::vector<std::uint32_t> groupVisibilityMasks(const std::vector<std::vector<std::uint8_t>>& visibilities) {
    std::vector<std::uint32_t> masks(visibilities.empty() ? 0 : visibilities.front().size(), 0u);
    const std::size_t maskedSteps = std::min(visibilities.size(), std::size_t(kMaxMaskedGroups * kTimeStepsPerTexel));
    for (std::size_t step = 0; step < maskedSteps; ++step) {
        const std::uint32_t bit = 1u << (step / kTimeStepsPerTexel);
        for (std::size_t brick = 0; brick < masks.size(); ++brick)
            if (visibilities[step][brick] != 0) masks[brick] |= bit;
    }
    return masks;
}

PackedAlignedAtlas::PackedAlignedAtlas(const Series& series, glm::ivec3 brickCounts, int maxTextureSize)
    : brickCounts_(brickCounts),
      validity_(packedValidityOf(series)),
      atlas_(Texture::create(GL_TEXTURE_3D)),
      validityTexture_(Texture::create(GL_TEXTURE_3D)),
      occupancy_(Texture::create(GL_TEXTURE_3D)),
      groupMasks_(Texture::create(GL_TEXTURE_3D)),
      changeBounds_(Texture::create(GL_TEXTURE_3D)),
      groupOrigins_(Buffer::create()) {
    const std::size_t groups = (series.size() + kTimeStepsPerTexel - 1) / kTimeStepsPerTexel;
    const glm::ivec3 dims = series.steps.front().dims();
    layout_ = planAtlas(std::vector<glm::ivec3>(groups, dims), maxTextureSize);

    glTextureStorage3D(atlas_.id(), 1, GL_RGBA16, layout_.size.x, layout_.size.y, layout_.size.z);
    atlas_.setFilter(GL_LINEAR, GL_LINEAR);
    atlas_.setClampToEdge();
    const bool perGroup = validity_ == PackedValidity::PerGroup;
    if (validity_ == PackedValidity::Shared) sharedValiditySize_ = dims;
    const glm::ivec3 validitySize = perGroup ? layout_.size : sharedValiditySize_;
    glTextureStorage3D(validityTexture_.id(), 1, perGroup ? GL_RGBA16 : GL_R16, validitySize.x, validitySize.y,
                       validitySize.z);
    validityTexture_.setFilter(GL_LINEAR, GL_LINEAR);
    validityTexture_.setClampToEdge();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (validity_ == PackedValidity::Shared) {
        const std::vector<std::uint16_t> validities = validityTexels(series.steps.front());
        glTextureSubImage3D(validityTexture_.id(), 0, 0, 0, 0, dims.x, dims.y, dims.z, GL_RED, GL_UNSIGNED_SHORT,
                            validities.data());
    }
    std::vector<glm::vec4> origins;
    for (std::size_t group = 0; group < groups; ++group) {
        const glm::ivec3 origin = layout_.brickOrigins[group];
        const std::vector<std::uint16_t> texels =
            packedGroupTexels(series, group, validity_ != PackedValidity::None);
        glTextureSubImage3D(atlas_.id(), 0, origin.x, origin.y, origin.z, dims.x, dims.y, dims.z, GL_RGBA,
                            GL_UNSIGNED_SHORT, texels.data());
        if (perGroup) {
            const std::vector<std::uint16_t> validities = packedGroupValidities(series, group);
            glTextureSubImage3D(validityTexture_.id(), 0, origin.x, origin.y, origin.z, dims.x, dims.y, dims.z,
                                GL_RGBA, GL_UNSIGNED_SHORT, validities.data());
        }
        origins.push_back(glm::vec4(glm::vec3(origin), 0.0f));
    }
    groupOrigins_.setData(std::as_bytes(std::span(origins)), GL_STATIC_DRAW);

    // With masks the occupancy sits beside each mask, and the occupancy texture is one texel, bound
    // but never read; without masks (more groups than a mask names) the other way round.
    const glm::ivec3 occupancySize = hasGroupMasks() ? glm::ivec3(1) : brickCounts;
    glTextureStorage3D(occupancy_.id(), 1, GL_R8UI, occupancySize.x, occupancySize.y, occupancySize.z);
    occupancy_.setFilter(GL_NEAREST, GL_NEAREST);
    occupancy_.setClampToEdge();
    const glm::ivec3 maskSize = hasGroupMasks() ? brickCounts : glm::ivec3(1);
    glTextureStorage3D(groupMasks_.id(), 1, GL_RG32UI, maskSize.x, maskSize.y, maskSize.z);
    groupMasks_.setFilter(GL_NEAREST, GL_NEAREST);
    groupMasks_.setClampToEdge();

    // A filtered RGBA16 density is a mix of the stored 16-bit values, each within half a unit of
    // the data: two units cover both ends of a range and the filter's own rounding.
    std::vector<float> bounds = brickChangeBounds(series.steps);
    for (float& bound : bounds) bound += 2.0f / 65535.0f;
    glTextureStorage3D(changeBounds_.id(), 1, GL_R32F, brickCounts.x, brickCounts.y, brickCounts.z);
    changeBounds_.setFilter(GL_NEAREST, GL_NEAREST);
    changeBounds_.setClampToEdge();
    glTextureSubImage3D(changeBounds_.id(), 0, 0, 0, 0, brickCounts.x, brickCounts.y, brickCounts.z, GL_RED, GL_FLOAT,
                        bounds.data());
}

std::size_t PackedAlignedAtlas::textureBytes() const {
    return atlas_.allocatedBytes() + validityTexture_.allocatedBytes() + occupancy_.allocatedBytes() +
           groupMasks_.allocatedBytes() + changeBounds_.allocatedBytes();
}

double PackedAlignedAtlas::updateOccupancy(const std::vector<std::vector<std::uint8_t>>& visibilities) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const std::vector<std::uint8_t> anyVisible = unionOfVisibilities(visibilities);
    const std::vector<std::uint8_t> reach = emptyBrickReach(anyVisible, brickCounts_);
    if (!hasGroupMasks()) {
        glTextureSubImage3D(occupancy_.id(), 0, 0, 0, 0, brickCounts_.x, brickCounts_.y, brickCounts_.z,
                            GL_RED_INTEGER, GL_UNSIGNED_BYTE, reach.data());
    } else {
        // Beside each mask its brick's occupancy texel, so that a sample reads both in one fetch.
        const std::vector<std::uint32_t> masks = groupVisibilityMasks(visibilities);
        std::vector<std::uint32_t> texels(2 * masks.size());
        for (std::size_t brick = 0; brick < masks.size(); ++brick) {
            texels[2 * brick] = reach[brick];
            texels[2 * brick + 1] = masks[brick];
        }
        glTextureSubImage3D(groupMasks_.id(), 0, 0, 0, 0, brickCounts_.x, brickCounts_.y, brickCounts_.z,
                            GL_RG_INTEGER, GL_UNSIGNED_INT, texels.data());
    }
    if (anyVisible.empty()) return 0.0;
    return double(std::count(anyVisible.begin(), anyVisible.end(), std::uint8_t(0))) / double(anyVisible.size());
}

void PackedAlignedAtlas::bind() const {
    atlas_.bindToUnit(contract::PACKED_ATLAS_UNIT);
    validityTexture_.bindToUnit(contract::PACKED_VALIDITY_UNIT);
    occupancy_.bindToUnit(contract::PACKED_OCCUPANCY_UNIT);
    groupMasks_.bindToUnit(contract::PACKED_GROUP_MASK_UNIT);
    changeBounds_.bindToUnit(contract::PACKED_CHANGE_BOUND_UNIT);
    groupOrigins_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::PACKED_GROUP_BUFFER);
}

}  // namespace tstyles
