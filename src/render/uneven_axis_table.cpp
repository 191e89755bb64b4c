// Flattening the node lists of all uneven axes into one array for the GPU.
#include "tstyles/render/uneven_axis_table.h"

#include <variant>

namespace tstyles {

UnevenAxisTable buildUnevenAxisTable(const Series& series) {
    UnevenAxisTable table;
    for (const TimeStep& step : series.steps) {
        glm::ivec4 first(-1);
        const RectilinearGrid* grid = std::get_if<RectilinearGrid>(&step.grid);  // other kinds: no uneven axes
        for (int axis = 0; grid && axis < 3; ++axis) {
            if (!grid->isUneven(axis)) continue;
            first[axis] = int(table.positions.size());
            for (const double position : grid->axisPositions[std::size_t(axis)])
                table.positions.push_back(float(position));
        }
        table.firstNode.push_back(first);
    }
    if (table.positions.empty()) table.positions.push_back(0.0f);
    return table;
}

glm::dvec3 voxelScale(const RectilinearGrid& grid) {
    glm::dvec3 scale = grid.spacing;
    for (int axis = 0; axis < 3; ++axis)
        if (grid.isUneven(axis)) scale[axis] = 1.0;
    return scale;
}

}  // namespace tstyles
