// Flattening the node lists of all uneven axes into arrays for the GPU.
#include "tstyles/render/uneven_axis_table.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <variant>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

constexpr int kMaxBuckets = 4096;

// One uneven axis in the table.
struct AxisEntry {
    int firstNode = -1;
    int firstCell = -1;
    int bucketCount = 0;
    float bucketsPerUnit = 0.0f;
};

// Appends the axis' nodes and its cell records: buckets half the finest gap wide where that takes
// at most kMaxBuckets, each with the cell of the last node at or below its start (at most
// count - 2). Sets `crowded` where the limit made them wider: a bucket may then hold several nodes.
AxisEntry appendAxis(const std::vector<double>& nodes, UnevenAxisTable& table) {
    AxisEntry entry;
    entry.firstNode = int(table.positions.size());
    for (const double position : nodes) table.positions.push_back(float(position));
    double finestGap = nodes.back();
    for (std::size_t k = 1; k < nodes.size(); ++k) finestGap = std::min(finestGap, nodes[k] - nodes[k - 1]);
    const double halfGapBuckets = std::ceil(2.0 * nodes.back() / finestGap);
    if (halfGapBuckets > double(kMaxBuckets)) table.crowdedBuckets = true;
    entry.bucketCount = int(std::clamp(halfGapBuckets, 1.0, double(kMaxBuckets)));
    const double width = nodes.back() / entry.bucketCount;
    entry.bucketsPerUnit = float(1.0 / width);
    entry.firstCell = int(table.cells.size());
    const int lastCell = int(nodes.size()) - 2;
    int lower = 0;
    for (int bucket = 0; bucket < entry.bucketCount; ++bucket) {
        while (lower < lastCell && nodes[std::size_t(lower) + 1] <= bucket * width) ++lower;
        const std::size_t next = std::size_t(lower) + 1;
        const double slopeBelow = 1.0 / (nodes[next] - nodes[next - 1]);
        const double slopeAbove = lower < lastCell ? 1.0 / (nodes[next + 1] - nodes[next]) : slopeBelow;
        table.cells.emplace_back(float(nodes[next]), float(next), float(slopeBelow), float(slopeAbove));
    }
    return entry;
}

}  // namespace

UnevenAxisTable buildUnevenAxisTable(const Series& series) {
    UnevenAxisTable table;
    std::map<std::vector<double>, AxisEntry> axes;
    for (const TimeStep& step : series.steps) {
        contract::UnevenAxisInfo info{glm::ivec4(-1), glm::ivec4(-1), glm::ivec4(0), glm::vec4(0.0f)};
        const RectilinearGrid* grid = std::get_if<RectilinearGrid>(&step.grid);  // other kinds: no uneven axes
        for (int axis = 0; grid && axis < 3; ++axis) {
            if (!grid->isUneven(axis)) continue;
            const std::vector<double>& nodes = grid->axisPositions[std::size_t(axis)];
            auto found = axes.find(nodes);
            if (found == axes.end()) found = axes.emplace(nodes, appendAxis(nodes, table)).first;
            info.firstNode[axis] = found->second.firstNode;
            info.firstCell[axis] = found->second.firstCell;
            info.bucketCount[axis] = found->second.bucketCount;
            info.bucketsPerUnit[axis] = found->second.bucketsPerUnit;
        }
        table.steps.push_back(info);
    }
    if (table.positions.empty()) table.positions.push_back(0.0f);
    if (table.cells.empty()) table.cells.emplace_back(0.0f);
    return table;
}

void requireCellsFit(const UnevenAxisTable& table, std::size_t maxTexels, const Series& series) {
    if (table.cells.size() <= maxTexels) return;
    throwInputError(series.manifestPath, "time_steps[].grid.positions",
                    "the uneven axes of the series' " + std::to_string(series.size()) + " time-steps need " +
                        std::to_string(table.cells.size()) + " lookup cells, more than this GPU's buffer textures hold (" +
                        std::to_string(maxTexels) + "); time-steps on the same levels share theirs");
}

float lookUpNodeIndex(const UnevenAxisTable& table, int step, int axis, int count, float position) {
    const contract::UnevenAxisInfo& info = table.steps[std::size_t(step)];
    const int bucket = std::clamp(int(position * info.bucketsPerUnit[axis]), 0, info.bucketCount[axis] - 1);
    const glm::vec4 cell = table.cells[std::size_t(info.firstCell[axis] + bucket)];
    if (!table.crowdedBuckets) {
        const float index = cell.y + (position - cell.x) * (position < cell.x ? cell.z : cell.w);
        return std::clamp(index, 0.0f, float(count - 1));
    }
    const auto node = [&](int index) { return table.positions[std::size_t(info.firstNode[axis] + index)]; };
    int low = int(cell.y) - 1;
    while (low < count - 2 && node(low + 1) <= position) ++low;
    while (low > 0 && node(low) > position) --low;
    return std::clamp(float(low) + (position - node(low)) / (node(low + 1) - node(low)), 0.0f, float(count - 1));
}

glm::dvec3 voxelScale(const RectilinearGrid& grid) {
    glm::dvec3 scale = grid.spacing;
    for (int axis = 0; axis < 3; ++axis)
        if (grid.isUneven(axis)) scale[axis] = 1.0;
    return scale;
}

}  // namespace tstyles
