// Fully aligned series (every time-step on the same grid with the same placement): the densities
// of four consecutive time-steps share one RGBA16 texel, so one filtered fetch gives four
// time-steps at a sample (shaders/packed_time_steps.glsl). All time-steps also share one brick
// grid, so empty-space skipping needs one occupancy texel per brick: visible where any time-step
// is. Built next to the ordinary atlas, which the naive raycaster and the gradients still read.
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

// Whether the packed path can render the series: at least two time-steps, all on one grid with one
// placement (isFullyAligned), evenly spaced rectilinear, stored at 16 bits (the packed atlas is
// RGBA16), without masks and without missing values (whose validity would need a channel of its own).
bool suitsPackedAtlas(const Series& series);

// The RGBA texels of one group of four time-steps (x fastest, four uint16 per voxel, time-step
// 4 * group + channel; channels past the last time-step are 0). GL-free.
std::vector<std::uint16_t> packedGroupTexels(const Series& series, std::size_t group);

// Per brick: visible (255) where any of the per-time-step visibilities (0 or 255, brickVisibility)
// is. All have the same length.
std::vector<std::uint8_t> unionOfVisibilities(const std::vector<std::vector<std::uint8_t>>& visibilities);

class PackedAlignedAtlas {
public:
    // Uploads every group of four time-steps; the series must suit (suitsPackedAtlas). Throws
    // InputError when the groups do not fit into one 3D texture.
    PackedAlignedAtlas(const Series& series, glm::ivec3 brickCounts, int maxTextureSize);

    int groupCount() const { return int(layout_.brickOrigins.size()); }
    const AtlasLayout& layout() const { return layout_; }
    std::size_t textureBytes() const;

    // The union of the time-steps' brick visibilities, per transfer-function change.
    void updateOccupancy(const std::vector<std::uint8_t>& unionVisibility);
    // Binds the packed atlas, its occupancy and the table of group origins.
    void bind() const;

private:
    AtlasLayout layout_;
    glm::ivec3 brickCounts_;
    Texture atlas_;
    Texture occupancy_;
    Buffer groupOrigins_;
};

}  // namespace tstyles
