// Fully aligned series (every time-step on the same grid with the same placement): the densities
// of four consecutive time-steps share one RGBA16 texel, so one filtered fetch gives four
// time-steps at a sample (shaders/packed_time_steps.glsl). With missing values the densities are
// premultiplied by validity and a second texture at the same place holds the validities, so that a
// density and its validity are filtered with the same weights (as the RG atlas does for one time-
// step): one R16 validity for all time-steps when they all miss the same voxels (land in a weather
// model: one extra fetch per sample), else four per RGBA16 texel (one extra fetch per group). All
// time-steps also share one brick grid, so empty-space skipping needs one occupancy texel per
// brick: visible where any time-step is. Built next to the ordinary atlas, which the naive
// raycaster and the gradients still read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/gl/objects.h"
#include "tstyles/render/atlas_layout.h"

namespace tstyles {

inline constexpr int kTimeStepsPerTexel = 4;

// Whether the packed path can render the series: at least two time-steps, all on one rectilinear
// grid (even or uneven axes) with one placement (isFullyAligned), stored at 16 bits (the packed
// atlas is RGBA16), without masks.
bool suitsPackedAtlas(const Series& series);
// The same whatever the series' precision: whether it would suit at 16 bits.
bool suitsPackedAtlasAt16Bits(const Series& series);

// The RGBA texels of one group of four time-steps (x fastest, four uint16 per voxel, time-step
// 4 * group + channel; channels past the last time-step are 0). With `withValidity` the densities
// are premultiplied by validity (0 where a value is missing), as densityTexels gives them. GL-free.
std::vector<std::uint16_t> packedGroupTexels(const Series& series, std::size_t group, bool withValidity = false);

// The validities of the same group: 65535 where the time-step has data, 0 where its value is
// missing and in channels past the last time-step. GL-free.
std::vector<std::uint16_t> packedGroupValidities(const Series& series, std::size_t group);

// How the packed atlas holds the validity of a series' values.
enum class PackedValidity {
    None,      // no value is missing
    Shared,    // every time-step misses the same voxels: one validity per voxel for all of them
    PerGroup,  // four validities per texel, like the densities
};
PackedValidity packedValidityOf(const Series& series);

// One validity per voxel (65535: data, 0: missing) of a time-step. GL-free.
std::vector<std::uint16_t> validityTexels(const TimeStep& step);

// Per brick: visible (255) where any of the per-time-step visibilities (0 or 255, brickVisibility)
// is. All have the same length.
std::vector<std::uint8_t> unionOfVisibilities(const std::vector<std::vector<std::uint8_t>>& visibilities);

// Groups of four time-steps that a brick's mask can name: the walk over the visible groups of a
// brick (PACKED_GROUP_MASKS) takes series of up to 4 * 32 time-steps.
inline constexpr int kMaxMaskedGroups = 32;

// Per brick: bit g set where a time-step of group g (time-steps 4g .. 4g + 3) is visible (its
// brick visibility, 0 or 255, is not 0). Groups from kMaxMaskedGroups on have no bit. GL-free.
std::vector<std::uint32_t> groupVisibilityMasks(const std::vector<std::vector<std::uint8_t>>& visibilities);

class PackedAlignedAtlas {
public:
    // Uploads every group of four time-steps and their bricks' change bounds (brickChangeBounds);
    // the series must suit (suitsPackedAtlas). Throws InputError when the groups do not fit into
    // one 3D texture.
    PackedAlignedAtlas(const Series& series, glm::ivec3 brickCounts, int maxTextureSize);

    int groupCount() const { return int(layout_.brickOrigins.size()); }
    const AtlasLayout& layout() const { return layout_; }
    PackedValidity validity() const { return validity_; }
    // The size of the shared validity texture (the grid's dims; PackedValidity::Shared).
    glm::ivec3 sharedValiditySize() const { return sharedValiditySize_; }
    std::size_t textureBytes() const;

    // Whether each brick's groups can be named in a mask (groupCount() <= kMaxMaskedGroups).
    bool hasGroupMasks() const { return groupCount() <= kMaxMaskedGroups; }

    // Per transfer-function change, from the time-steps' brick visibilities: how far the empty
    // bricks of their union reach (emptyBrickReach) and, with group masks, which groups each brick
    // shows (groupVisibilityMasks), the two side by side in the group-mask texture; without masks
    // the reach goes to the occupancy texture. Returns the share of bricks empty in every time-step.
    double updateOccupancy(const std::vector<std::vector<std::uint8_t>>& visibilities);
    // Whether the bricks' change bounds hold for every place of the series: where time-steps miss
    // different voxels (PackedValidity::PerGroup), a place may have data in one time-step only, whose
    // compositor then reports a change above any bound.
    bool boundsChange() const { return validity_ != PackedValidity::PerGroup; }
    // Binds the packed atlas, its validities, its occupancy, its change bounds and the table of
    // group origins.
    void bind() const;

private:
    AtlasLayout layout_;
    glm::ivec3 brickCounts_;
    PackedValidity validity_;
    glm::ivec3 sharedValiditySize_{1};
    Texture atlas_;
    // PerGroup: RGBA16 in atlas_'s layout; Shared: R16 of the grid's dims; None: one texel.
    Texture validityTexture_;
    Texture occupancy_;  // R8UI, one texel per brick without group masks, else one texel
    // RG32UI, one texel per brick (hasGroupMasks): the occupancy texel and the group mask.
    Texture groupMasks_;
    // R32F, one texel per brick: brickChangeBounds, raised by the rounding of the 16-bit densities.
    Texture changeBounds_;
    Buffer groupOrigins_;
};

}  // namespace tstyles
