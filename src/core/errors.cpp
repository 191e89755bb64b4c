// Formatting of user-facing input errors.
#include "tstyles/core/errors.h"

namespace tstyles {

std::string describeInputProblem(const std::filesystem::path& file, const std::string& field,
                                 const std::string& problem) {
    std::string message = file.empty() ? std::string("<input>") : file.string();
    if (!field.empty()) message += ": " + field;
    message += ": " + problem;
    return message;
}

void throwInputError(const std::filesystem::path& file, const std::string& field,
                     const std::string& problem) {
    throw InputError(describeInputProblem(file, field, problem));
}

}  // namespace tstyles
