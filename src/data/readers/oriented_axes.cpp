// Orthogonal axes in, spacing and rotation out; shear is refused rather than silently dropped.
#include "oriented_axes.h"

#include <algorithm>
#include <cmath>

#include "tstyles/core/errors.h"

namespace tstyles {

OrientedAxes orientAxes(const glm::dvec3& origin, const std::array<glm::dvec3, 3>& axes, const glm::ivec3& dims,
                        const std::filesystem::path& file, const std::string& field) {
    OrientedAxes result;
    std::array<glm::dvec3, 3> unit{};
    for (int axis = 0; axis < 3; ++axis) {
        const double length = glm::length(axes[std::size_t(axis)]);
        if (!(length > 0.0) || !std::isfinite(length))
            throwInputError(file, field, "axis " + std::to_string(axis) + " has no finite, non-zero voxel step");
        result.spacing[axis] = length;
        unit[std::size_t(axis)] = axes[std::size_t(axis)] / length;
    }
    for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b)
            if (std::abs(glm::dot(unit[std::size_t(a)], unit[std::size_t(b)])) > 1e-4)
                throwInputError(file, field,
                                "axes " + std::to_string(a) + " and " + std::to_string(b) +
                                    " are not orthogonal: sheared grids are not supported");
    glm::dvec3 start = origin;
    if (glm::determinant(glm::dmat3(unit[0], unit[1], unit[2])) < 0.0) {
        // Reverse x: the last voxel along x becomes the first, and its step points the other way.
        start += double(dims.x - 1) * axes[0];
        unit[0] = -unit[0];
        result.mirrorX = true;
    }
    result.placement.origin = start;
    result.placement.rotation = glm::normalize(glm::quat_cast(glm::dmat3(unit[0], unit[1], unit[2])));
    return result;
}

void mirrorAlongX(std::vector<float>& values, const glm::ivec3& dims) {
    const std::size_t nx = std::size_t(dims.x);
    for (std::size_t row = 0; row + nx <= values.size(); row += nx)
        std::reverse(values.begin() + std::ptrdiff_t(row), values.begin() + std::ptrdiff_t(row + nx));
}

}  // namespace tstyles
