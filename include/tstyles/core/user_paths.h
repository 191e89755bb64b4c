// Questions about paths the user wrote (command line, scene, manifest, suite, keyframes): asked so that a
// name the system refuses is an InputError naming the file and the field, never a std::filesystem_error.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace tstyles {

// Where a path was written: the file that names it and the field ("stf.color[2].style"). On the command
// line there is no such file: `file` is empty, the path itself is named and the option is the field.
struct PathSource {
    std::filesystem::path file;
    std::string field;
};

enum class PathKind { Missing, RegularFile, Folder, Other };

// An InputError unless `name` is a path the system can look up: no NUL, no component longer than
// NAME_MAX, not longer than PATH_MAX. Takes the text so that a NUL from JSON ("a\u0000b") is seen.
void requireUsablePathName(const PathSource& source, std::string_view name);

// What is at `path`, links followed. Nothing there, or a missing folder on the way, is Missing; a
// name too long, a loop of links, no permission or a file used as a folder is an InputError.
PathKind userPathKind(const PathSource& source, const std::filesystem::path& path);

// An InputError unless `path` is a regular file (`what` names it: "scene file", "style image").
void requireUserFile(const PathSource& source, const std::filesystem::path& path, const std::string& what);

// `path` made absolute and normal, without the exception std::filesystem::absolute may throw.
std::filesystem::path userAbsolutePath(const PathSource& source, const std::filesystem::path& path);

// A file about to be written: its name usable, its folder an existing folder, and nothing at `path`
// or a regular file (a folder, FIFO or device is refused, not replaced). `what` names the file.
void requireOutputFile(const PathSource& source, const std::filesystem::path& path, const std::string& what);

// A folder about to be written (a dataset, frames, a report): its name usable, its parent an existing
// folder, and nothing at `path` or a folder.
void requireOutputFolder(const PathSource& source, const std::filesystem::path& path, const std::string& what);

// The one place a file-system failure on a user's path becomes an InputError: the problem in words
// ("the name is too long for the file system (5000 characters)"), naming the file and the field.
[[noreturn]] void throwUserPathError(const PathSource& source, const std::filesystem::path& path,
                                     const std::error_code& error);

// Runs `call`, which touches the user's `path` with a throwing std::filesystem function, turning a
// std::filesystem_error into the InputError above.
template <typename Call>
decltype(auto) withUserPath(const PathSource& source, const std::filesystem::path& path, Call&& call) {
    try {
        return call();
    } catch (const std::filesystem::filesystem_error& error) {
        throwUserPathError(source, path, error.code());
    }
}

}  // namespace tstyles
