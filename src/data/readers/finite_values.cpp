// The first non-finite value, located in (x, y, z), so the user can find it in their own tools.
#include "finite_values.h"

#include <cmath>

#include "tstyles/core/errors.h"

namespace tstyles {

void requireFiniteValues(const std::vector<float>& values, const glm::ivec3& dims, const std::filesystem::path& file,
                         std::size_t step, const std::string& remedy) {
    for (std::size_t index = 0; index < values.size(); ++index) {
        if (std::isfinite(values[index])) continue;
        const std::size_t nx = std::size_t(dims.x);
        const std::size_t ny = std::size_t(dims.y);
        throwInputError(file, "",
                        "time-step " + std::to_string(step) + " holds " + (std::isnan(values[index]) ? "NaN" : "Inf") +
                            " at voxel (x, y, z) = (" + std::to_string(index % nx) + ", " +
                            std::to_string((index / nx) % ny) + ", " + std::to_string(index / (nx * ny)) +
                            ") that the file does not declare as missing" + (remedy.empty() ? "" : ": " + remedy));
    }
}

}  // namespace tstyles
