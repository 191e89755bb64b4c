// Error types shared by every layer. User mistakes (bad files, bad scene keys) are InputError and
// end in exit code 2; a machine without a usable OpenGL 4.5 core context is GlUnavailableError (3).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace tstyles {

// Bad input from the user: a file, dataset or scene that cannot be used. The message names the
// file, the field and the problem, so the front end can print it as it is.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// No OpenGL 4.5 core context could be created; the message lists what was tried.
class GlUnavailableError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "file: field: problem", the one shape every input error takes.
std::string describeInputProblem(const std::filesystem::path& file, const std::string& field,
                                 const std::string& problem);

[[noreturn]] void throwInputError(const std::filesystem::path& file, const std::string& field,
                                  const std::string& problem);

}  // namespace tstyles
