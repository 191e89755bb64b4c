// The node lists of uneven axes as the shaders read them (shaders/uneven_axes.glsl), and the scale
// of each time-step's worldToVoxel: 1 / spacing along even axes, 1 (grid-local position) along
// uneven ones, which the node lists then turn into node indices. GL-free.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"

namespace tstyles {

struct UnevenAxisTable {
    // Per time-step, per axis: the index of the axis' first node in `positions`, or -1 (even).
    std::vector<glm::ivec4> firstNode;
    // Every uneven axis' nodes; never empty (one unused 0), so the buffer can always be bound.
    std::vector<float> positions;
};

UnevenAxisTable buildUnevenAxisTable(const Series& series);

// The per-axis distance that worldToVoxel divides by: the spacing, or 1 along an uneven axis.
glm::dvec3 voxelScale(const RectilinearGrid& grid);

}  // namespace tstyles
