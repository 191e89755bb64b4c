// Paths the user wrote, looked up with error codes: every refusal of the system (ENAMETOOLONG, ELOOP,
// EACCES, ENOTDIR) becomes one InputError naming the file and the field (user_paths.h).
#include "tstyles/core/user_paths.h"

#include <algorithm>
#include <cerrno>
#include <climits>

#include <unistd.h>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

// Linux's limits for one name and a whole path (the final NUL counted in PATH_MAX). File systems with
// smaller limits still answer ENAMETOOLONG, which throwUserPathError words the same way.
constexpr std::size_t kLongestName = NAME_MAX;
constexpr std::size_t kLongestPath = PATH_MAX - 1;

std::size_t longestComponent(std::string_view name) {
    std::size_t longest = 0;
    std::size_t start = 0;
    while (start <= name.size()) {
        const std::size_t slash = std::min(name.find('/', start), name.size());
        longest = std::max(longest, slash - start);
        start = slash + 1;
    }
    return longest;
}

// Names the path's file and field: on the command line the path is the file; in a scene or manifest the
// path follows the field, so that a long dataset path is still seen whole.
[[noreturn]] void refuse(const PathSource& source, const std::filesystem::path& path, const std::string& problem,
                         bool showPath = true) {
    if (source.file.empty()) throwInputError(path, source.field, problem);
    throwInputError(source.file, source.field, showPath ? path.string() + ": " + problem : problem);
}

std::string nameTooLongProblem(std::string_view name) {
    const std::size_t longest = longestComponent(name);
    // A file system with a smaller limit than Linux's answers ENAMETOOLONG for a shorter name.
    if (longest > kLongestName || name.size() <= kLongestPath)
        return "the name is too long for the file system (" + std::to_string(longest) + " characters)";
    return "the path is too long for the file system (" + std::to_string(name.size()) + " characters, at most " +
           std::to_string(kLongestPath) + ")";
}

// "a scene file", "an image file".
std::string withArticle(const std::string& what) {
    const bool vowel = !what.empty() && std::string_view("aeiou").find(what.front()) != std::string_view::npos;
    return (vowel ? "an " : "a ") + what;
}

std::filesystem::path folderOf(const std::filesystem::path& path) {
    return path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
}

// The folder something is written into: there, a folder, and open to us (root is never refused).
void requireWritableFolder(const PathSource& source, const std::filesystem::path& path) {
    requireUsablePathName(source, path.native());
    const std::filesystem::path folder = folderOf(path);
    const PathKind kind = userPathKind(source, folder);
    if (kind == PathKind::Missing) refuse(source, path, "the folder " + folder.string() + " does not exist");
    if (kind != PathKind::Folder) refuse(source, path, folder.string() + " is a file, not a folder");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        refuse(source, path, "no permission to write in the folder " + folder.string());
}

}  // namespace

void requireUsablePathName(const PathSource& source, std::string_view name) {
    // A NUL would end the name early in the system call: another file than the one written.
    if (name.find('\0') != std::string_view::npos)
        refuse(source, std::string(name.substr(0, name.find('\0'))), "the name holds a NUL character");
    if (longestComponent(name) > kLongestName || name.size() > kLongestPath)
        refuse(source, std::string(name), nameTooLongProblem(name), false);
}

PathKind userPathKind(const PathSource& source, const std::filesystem::path& path) {
    requireUsablePathName(source, path.native());
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (error && error.value() != ENOENT) throwUserPathError(source, path, error);
    switch (status.type()) {
        case std::filesystem::file_type::not_found: return PathKind::Missing;
        case std::filesystem::file_type::regular: return PathKind::RegularFile;
        case std::filesystem::file_type::directory: return PathKind::Folder;
        default: return PathKind::Other;
    }
}

void requireUserFile(const PathSource& source, const std::filesystem::path& path, const std::string& what) {
    switch (userPathKind(source, path)) {
        case PathKind::RegularFile: return;
        case PathKind::Missing: refuse(source, path, "no such " + what);
        case PathKind::Folder: refuse(source, path, "is a folder, not " + withArticle(what));
        case PathKind::Other:
            refuse(source, path,
                   "is not a regular file (a device, FIFO or socket cannot be read as " + withArticle(what) + ")");
    }
}

std::filesystem::path userAbsolutePath(const PathSource& source, const std::filesystem::path& path) {
    requireUsablePathName(source, path.native());
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    if (error) throwUserPathError(source, path, error);
    return absolute.lexically_normal();
}

void requireOutputFile(const PathSource& source, const std::filesystem::path& path, const std::string& what) {
    requireWritableFolder(source, path);
    const PathKind kind = userPathKind(source, path);
    if (kind == PathKind::Folder) refuse(source, path, "is a folder, not " + withArticle(what));
    if (kind == PathKind::Other)
        refuse(source, path, "is not a regular file (a FIFO, device or socket), not replaced by the " + what);
}

void requireOutputFolder(const PathSource& source, const std::filesystem::path& path, const std::string& what) {
    requireWritableFolder(source, path);
    const PathKind kind = userPathKind(source, path);
    if (kind != PathKind::Missing && kind != PathKind::Folder)
        refuse(source, path, "is a file, not " + withArticle(what));
}

void throwUserPathError(const PathSource& source, const std::filesystem::path& path, const std::error_code& error) {
    switch (error.value()) {
        case ENAMETOOLONG: refuse(source, path, nameTooLongProblem(path.native()), false);
        case ELOOP: refuse(source, path, "a loop of symbolic links (or too many links in a row)");
        case EACCES: refuse(source, path, "no permission to reach it (a folder on the way is closed to us)");
        case ENOTDIR: refuse(source, path, "a part of the path is a file, not a folder");
        case ENOENT: refuse(source, path, "no such file or folder");
        default: refuse(source, path, "cannot be reached: " + error.message());
    }
}

}  // namespace tstyles
