// Reading a grid's "dims" (grid_dims_field.h).
#include "grid_dims_field.h"

namespace tstyles {

glm::ivec3 readGridDims(const JsonField& dims, std::uint64_t maxCount, const GridDimsWording& wording) {
    if (dims.arraySize() != 3) dims.fail(wording.expectedThree);
    glm::ivec3 result(0);
    std::uint64_t total = 1;
    for (int axis = 0; axis < 3; ++axis) {
        const JsonField count = dims.element(std::size_t(axis));
        result[axis] = count.integer();
        if (result[axis] < 2)
            count.fail("must be at least 2, found " + std::to_string(result[axis]) + ": " + wording.whyTwo);
        total *= std::uint64_t(result[axis]);  // each factor < 2^31 and the running product is checked
        if (total > maxCount) dims.fail(wording.tooMany);
    }
    return result;
}

}  // namespace tstyles
