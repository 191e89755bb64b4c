// A structured grid whose mapping is known in closed form: a box of dims nodes `spacing` apart,
// bent by sine waves. For tests and the demo dataset (tools/generate_warped_box).
//   x = spacing * i + amplitude.x * sin(pi * t)
//   y = spacing * j + amplitude.y * sin(pi * s)
//   z = spacing * k + amplitude.z * sin(pi * s)
// with s = i / (nx - 1) and t = j / (ny - 1): each face bulges by the amplitude at its middle.
#pragma once

#include <glm/glm.hpp>

#include "tstyles/data/structured_grid.h"

namespace tstyles {

struct WarpedBox {
    glm::ivec3 dims{17, 17, 9};
    double spacing = 1.0 / 16.0;
    glm::dvec3 amplitude{0.15, 0.1, 0.0};

    // The closed-form position of computational coordinates (i, j, k), fractional allowed.
    glm::dvec3 position(glm::dvec3 computational) const;
    // The grid: nodes at the integer computational coordinates.
    StructuredGrid grid() const;
};

}  // namespace tstyles
