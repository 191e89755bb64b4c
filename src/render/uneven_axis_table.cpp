// Flattening the node lists of all uneven axes into one array for the GPU.
#include "tstyles/render/uneven_axis_table.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace tstyles {
namespace {

constexpr int kMaxBuckets = 4096;

// After an axis' nodes: 1 / bucket width, the bucket count, then each bucket's lower node (the
// last node at or below the bucket's start, at most count - 2). Buckets are half the finest gap
// wide where that takes at most kMaxBuckets, so a lookup lands on its node or the one before (one
// step up; one down where float rounding picked the next bucket). Returns false where the limit
// made them wider: a bucket may then hold several nodes, and the lookup has to walk.
bool appendBuckets(const std::vector<double>& nodes, std::vector<float>& positions) {
    double finestGap = nodes.back();
    for (std::size_t k = 1; k < nodes.size(); ++k) finestGap = std::min(finestGap, nodes[k] - nodes[k - 1]);
    const double halfGapBuckets = std::ceil(2.0 * nodes.back() / finestGap);
    const int buckets = int(std::clamp(halfGapBuckets, 1.0, double(kMaxBuckets)));
    const double width = nodes.back() / buckets;
    positions.push_back(float(1.0 / width));
    positions.push_back(float(buckets));
    const int lastCell = int(nodes.size()) - 2;
    int lower = 0;
    for (int bucket = 0; bucket < buckets; ++bucket) {
        while (lower < lastCell && nodes[std::size_t(lower) + 1] <= bucket * width) ++lower;
        positions.push_back(float(lower));
    }
    return halfGapBuckets <= double(kMaxBuckets);
}

}  // namespace

UnevenAxisTable buildUnevenAxisTable(const Series& series) {
    UnevenAxisTable table;
    for (const TimeStep& step : series.steps) {
        glm::ivec4 first(-1);
        const RectilinearGrid* grid = std::get_if<RectilinearGrid>(&step.grid);  // other kinds: no uneven axes
        for (int axis = 0; grid && axis < 3; ++axis) {
            if (!grid->isUneven(axis)) continue;
            first[axis] = int(table.positions.size());
            const std::vector<double>& nodes = grid->axisPositions[std::size_t(axis)];
            for (const double position : nodes) table.positions.push_back(float(position));
            if (!appendBuckets(nodes, table.positions)) table.crowdedBuckets = true;
        }
        table.firstNode.push_back(first);
    }
    if (table.positions.empty()) table.positions.push_back(0.0f);
    return table;
}

float lookUpNodeIndex(const UnevenAxisTable& table, int first, int count, float position) {
    const auto node = [&](int index) { return table.positions[std::size_t(first + index)]; };
    const int buckets = int(node(count + 1));
    const int bucket = std::clamp(int(position * node(count)), 0, buckets - 1);
    int low = int(node(count + 2 + bucket));
    if (table.crowdedBuckets) {
        while (low < count - 2 && node(low + 1) <= position) ++low;
        while (low > 0 && node(low) > position) --low;
    } else {
        if (low < count - 2 && node(low + 1) <= position) ++low;
        if (low > 0 && node(low) > position) --low;
    }
    return std::clamp(float(low) + (position - node(low)) / (node(low + 1) - node(low)), 0.0f, float(count - 1));
}

glm::dvec3 voxelScale(const RectilinearGrid& grid) {
    glm::dvec3 scale = grid.spacing;
    for (int axis = 0; axis < 3; ++axis)
        if (grid.isUneven(axis)) scale[axis] = 1.0;
    return scale;
}

}  // namespace tstyles
