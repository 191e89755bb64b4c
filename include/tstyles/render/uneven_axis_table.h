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
    // Every uneven axis' nodes, each list followed by its bucket lookup (1 / bucket width, bucket
    // count, each bucket's lower node), so that a position finds its cell with one read and a step
    // or two instead of a binary search; never empty (one unused 0), so the buffer can always be bound.
    std::vector<float> positions;
    // Whether some axis needed more buckets than the table holds (gaps over more than three orders
    // of magnitude, such as ocean depths): a bucket may then hold several nodes, and the lookup
    // walks from its bucket's node (the shaders' UNEVEN_AXIS_WALK) instead of taking one step,
    // which costs llvmpipe loop passes at every sample (docs/architecture.md).
    bool crowdedBuckets = false;
};

UnevenAxisTable buildUnevenAxisTable(const Series& series);

// The fractional node index of grid-local `position` along the axis whose `count` nodes start at
// `first`, through its bucket lookup, clamped to [0, count - 1]: what shaders/uneven_axes.glsl's
// nodeIndexOf computes, with UNEVEN_AXIS_WALK as table.crowdedBuckets (the tests check it against
// data/grid_axes.h).
float lookUpNodeIndex(const UnevenAxisTable& table, int first, int count, float position);

// The per-axis distance that worldToVoxel divides by: the spacing, or 1 along an uneven axis.
glm::dvec3 voxelScale(const RectilinearGrid& grid);

}  // namespace tstyles
