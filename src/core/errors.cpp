// Formatting of user-facing input errors.
#include "tstyles/core/errors.h"

namespace tstyles {

std::string describeInputProblem(const std::filesystem::path& file, const std::string& field,
                                 const std::string& problem) {
    // Problems with a command-line option have no file: the option is the field.
    std::string message = file.string();
    if (!field.empty()) message += (message.empty() ? "" : ": ") + field;
    message += (message.empty() ? "" : ": ") + problem;
    return message;
}

void throwInputError(const std::filesystem::path& file, const std::string& field,
                     const std::string& problem) {
    throw InputError(describeInputProblem(file, field, problem));
}

}  // namespace tstyles
