// The files the viewer opened lately, newest first, kept across restarts in
// $XDG_STATE_HOME/tstyles/recent (else ~/.local/state/tstyles/recent), one absolute path a line.
#pragma once

#include <filesystem>
#include <vector>

namespace tstyles::viewer {

// Where the list lives, from the values of XDG_STATE_HOME and HOME (either may be null); empty
// when neither says (then nothing is remembered).
std::filesystem::path recentFilesLocation(const char* xdgStateHome, const char* home);

class RecentFiles {
public:
    static constexpr std::size_t kMostRemembered = 10;

    // Reads the list at `location` (none yet, or unreadable: an empty list).
    explicit RecentFiles(std::filesystem::path location);

    // Puts `opened` first (once) and writes the list; a list that cannot be written is reported
    // on stderr and kept for this session only.
    void remember(const std::filesystem::path& opened);
    // The remembered paths that still exist, newest first.
    std::vector<std::filesystem::path> existing() const;

private:
    std::filesystem::path location_;
    std::vector<std::filesystem::path> paths_;
};

}  // namespace tstyles::viewer
