// The warped box: a curvilinear grid with a closed-form mapping.
#include "tstyles/data/warped_box.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace tstyles {

glm::dvec3 WarpedBox::position(glm::dvec3 computational) const {
    const double s = computational.x / double(dims.x - 1);
    const double t = computational.y / double(dims.y - 1);
    return spacing * computational + glm::dvec3(amplitude.x * std::sin(std::numbers::pi * t),
                                                amplitude.y * std::sin(std::numbers::pi * s),
                                                amplitude.z * std::sin(std::numbers::pi * s));
}

StructuredGrid WarpedBox::grid() const {
    std::vector<glm::vec3> nodes;
    nodes.reserve(std::size_t(dims.x) * dims.y * dims.z);
    for (int k = 0; k < dims.z; ++k)
        for (int j = 0; j < dims.y; ++j)
            for (int i = 0; i < dims.x; ++i) nodes.push_back(glm::vec3(position(glm::dvec3(i, j, k))));
    return makeStructuredGrid(dims, std::move(nodes));
}

}  // namespace tstyles
