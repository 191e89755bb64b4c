// The first infinite value, located in (x, y, z), so the user can find it in their own tools.
#include "infinite_values.h"

#include <cmath>
#include <string>

#include "tstyles/core/errors.h"

namespace tstyles {

void refuseInfinities(const std::vector<float>& values, const glm::ivec3& dims, const std::filesystem::path& file,
                      std::size_t step) {
    for (std::size_t index = 0; index < values.size(); ++index) {
        if (!std::isinf(values[index])) continue;
        const std::size_t nx = std::size_t(dims.x);
        const std::size_t ny = std::size_t(dims.y);
        throwInputError(file, "",
                        "time-step " + std::to_string(step) + " holds " + (values[index] > 0 ? "Inf" : "-Inf") +
                            " at voxel (x, y, z) = (" + std::to_string(index % nx) + ", " +
                            std::to_string((index / nx) % ny) + ", " + std::to_string(index / (nx * ny)) +
                            "): only NaN (or a declared fill value) marks missing data");
    }
}

}  // namespace tstyles
