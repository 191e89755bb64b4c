// The viewer's recent-files list: where it lives, newest first, once each, and kept across restarts.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "viewer/recent_files.h"

namespace {

using tstyles::viewer::RecentFiles;
using tstyles::viewer::recentFilesLocation;

std::filesystem::path freshFolder(const std::string& name) {
    const auto folder = std::filesystem::temp_directory_path() / ("tstyles_recent_files_" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

TEST(RecentFiles, LivesInXdgStateHomeElseHomeLocalState) {
    EXPECT_EQ(recentFilesLocation("/state", "/home/a"), "/state/tstyles/recent");
    EXPECT_EQ(recentFilesLocation(nullptr, "/home/a"), "/home/a/.local/state/tstyles/recent");
    EXPECT_EQ(recentFilesLocation("relative", "/home/a"), "/home/a/.local/state/tstyles/recent");
    EXPECT_EQ(recentFilesLocation("", "/home/a"), "/home/a/.local/state/tstyles/recent");
    EXPECT_EQ(recentFilesLocation(nullptr, nullptr), "");
}

TEST(RecentFiles, NewestFirstOnceEachAndKeptAcrossRestarts) {
    const auto folder = freshFolder("restarts");
    for (const char* name : {"a.nc", "b.nii", "c.json"}) std::ofstream(folder / name) << "x";
    const auto list = folder / "state/tstyles/recent";
    {
        RecentFiles recent(list);
        EXPECT_TRUE(recent.existing().empty());
        recent.remember(folder / "a.nc");
        recent.remember(folder / "b.nii");
        recent.remember(folder / "c.json");
        recent.remember(folder / "a.nc");
    }
    const RecentFiles restarted(list);
    const std::vector<std::filesystem::path> expected = {folder / "a.nc", folder / "c.json", folder / "b.nii"};
    EXPECT_EQ(restarted.existing(), expected);
}

TEST(RecentFiles, KeepsTheNewestTenAndListsOnlyWhatStillExists) {
    const auto folder = freshFolder("ten");
    const auto list = folder / "recent";
    RecentFiles recent(list);
    for (int i = 0; i < 12; ++i) {
        std::ofstream(folder / (std::to_string(i) + ".nc")) << "x";
        recent.remember(folder / (std::to_string(i) + ".nc"));
    }
    std::filesystem::remove(folder / "11.nc");
    const auto existing = RecentFiles(list).existing();
    ASSERT_EQ(existing.size(), 9u);  // 11.nc .. 2.nc are kept, and 11.nc is gone
    EXPECT_EQ(existing.front(), folder / "10.nc");
    EXPECT_EQ(existing.back(), folder / "2.nc");
}

TEST(RecentFiles, RelativeLinesOfAHandEditedListAreIgnored) {
    const auto folder = freshFolder("hand_edited");
    std::ofstream(folder / "a.nc") << "x";
    std::ofstream(folder / "recent") << "a.nc\n" << (folder / "a.nc").string() << "\n\n";
    const std::vector<std::filesystem::path> expected = {folder / "a.nc"};
    EXPECT_EQ(RecentFiles(folder / "recent").existing(), expected);
}

}  // namespace
