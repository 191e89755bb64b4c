// The recent-files list: read once when the viewer starts, rewritten whole after each opening.
#include "recent_files.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>

#include "tstyles/core/atomic_file.h"

namespace tstyles::viewer {

std::filesystem::path recentFilesLocation(const char* xdgStateHome, const char* home) {
    // The XDG base directory specification: a relative XDG_STATE_HOME is invalid and ignored.
    if (xdgStateHome != nullptr && std::filesystem::path(xdgStateHome).is_absolute())
        return std::filesystem::path(xdgStateHome) / "tstyles" / "recent";
    if (home != nullptr && *home != 0) return std::filesystem::path(home) / ".local" / "state" / "tstyles" / "recent";
    return {};
}

RecentFiles::RecentFiles(std::filesystem::path location) : location_(std::move(location)) {
    if (location_.empty()) return;
    std::ifstream in(location_);
    std::string line;
    // Only absolute paths: the list is ours, but a hand-edited line must not open relative to
    // wherever the viewer happens to start.
    while (paths_.size() < kMostRemembered && std::getline(in, line))
        if (std::filesystem::path(line).is_absolute() &&
            std::find(paths_.begin(), paths_.end(), line) == paths_.end())
            paths_.emplace_back(line);
}

void RecentFiles::remember(const std::filesystem::path& opened) {
    const std::filesystem::path path = std::filesystem::absolute(opened).lexically_normal();
    if (path.string().find('\n') != std::string::npos) return;  // one path a line: it would read back as two
    paths_.erase(std::remove(paths_.begin(), paths_.end(), path), paths_.end());
    paths_.insert(paths_.begin(), path);
    if (paths_.size() > kMostRemembered) paths_.resize(kMostRemembered);
    if (location_.empty()) return;
    std::string text;
    for (const auto& remembered : paths_) text += remembered.string() + "\n";
    try {
        std::filesystem::create_directories(location_.parent_path());
        writeFileAtomically(location_, text);
    } catch (const std::exception& error) {
        std::cerr << "tstyles view: the recent-files list " << location_.string() << " cannot be written: "
                  << error.what() << "\n";
    }
}

std::vector<std::filesystem::path> RecentFiles::existing() const {
    std::vector<std::filesystem::path> found;
    for (const auto& path : paths_) {
        std::error_code error;
        if (std::filesystem::exists(path, error)) found.push_back(path);
    }
    return found;
}

}  // namespace tstyles::viewer
