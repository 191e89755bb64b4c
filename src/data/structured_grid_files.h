// Reading the grid of a structured time-step from a manifest: dims and a coordinates file of
// float32 x, y, z per node. Time-steps naming the same file share one grid (and one inverse map).
#pragma once

#include <cstddef>
#include <map>
#include <utility>

#include "grid_dims_field.h"
#include "tstyles/data/structured_grid.h"

namespace tstyles {

class StructuredGridFiles {
public:
    // `field` is the time-step's "grid" object with type "structured". Errors name the field, the
    // time-step and the problem (size mismatch, non-finite coordinates, degenerate or inverted cells).
    StructuredGrid read(const JsonField& field, std::size_t stepIndex);

private:
    std::map<std::pair<std::filesystem::path, std::array<int, 3>>, StructuredGrid> grids_;
};

}  // namespace tstyles
