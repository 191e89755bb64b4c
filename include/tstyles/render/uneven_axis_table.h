// The node lists of uneven axes as the shaders read them (shaders/uneven_axes.glsl), and the scale
// of each time-step's worldToVoxel: 1 / spacing along even axes, 1 (grid-local position) along
// uneven ones, which the node lists then turn into node indices. GL-free.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/render/shader_contract.h"

namespace tstyles {

struct UnevenAxisTable {
    // Per time-step: where each uneven axis' nodes and bucket cells start (firstNode -1 along even
    // axes). Time-steps with the same nodes along an axis share them (a series on one grid holds
    // one list).
    std::vector<contract::UnevenAxisInfo> steps;
    // Every distinct uneven axis' nodes, each list increasing from 0; never empty (one unused 0), so
    // that the buffer can always be bound.
    std::vector<float> positions;
    // Per axis, per bucket of its equal-width buckets: the cell record (x: the first node after the
    // bucket's start, y: that node's index, z and w: node indices per grid-local unit in the cells
    // below and above it, the same where it is the last node). A position p in the bucket has the
    // node index y + (p - x) * (p < x ? z : w): one fetch, no search. Buckets are at most half the
    // finest gap wide, so a bucket holds at most the one node x; never empty either.
    std::vector<glm::vec4> cells;
    // Whether some axis needed more buckets than the table holds (gaps over more than three orders
    // of magnitude, such as ocean depths): a bucket may then hold several nodes, its record gives only
    // the cell it starts in, and the lookup walks from there (the shaders' UNEVEN_AXIS_WALK), which
    // costs llvmpipe loop passes at every sample (docs/architecture.md).
    bool crowdedBuckets = false;
};

UnevenAxisTable buildUnevenAxisTable(const Series& series);

// Throws an InputError naming the series' manifest where the table's cell records are more than a
// buffer texture of the GPU holds (GL_MAX_TEXTURE_BUFFER_SIZE, at least 65536): many time-steps,
// each on levels of its own.
void requireCellsFit(const UnevenAxisTable& table, std::size_t maxTexels, const Series& series);

// The fractional node index of grid-local `position` along axis `axis` of time-step `step`, whose
// grid has `count` nodes along it, clamped to [0, count - 1]: what shaders/uneven_axes.glsl's
// nodeIndexIn computes, with UNEVEN_AXIS_WALK as table.crowdedBuckets (the tests check it against
// data/grid_axes.h).
float lookUpNodeIndex(const UnevenAxisTable& table, int step, int axis, int count, float position);

// The per-axis distance that worldToVoxel divides by: the spacing, or 1 along an uneven axis.
glm::dvec3 voxelScale(const RectilinearGrid& grid);

}  // namespace tstyles
