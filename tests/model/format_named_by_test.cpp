// formatNamedBy: the format a file browser shows beside a file or folder, from its name alone.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tstyles/data/series_opener.h"

namespace {

std::filesystem::path freshFolder(const std::string& name) {
    const auto folder = std::filesystem::temp_directory_path() / ("tstyles_format_named_by_" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

TEST(FormatNamedBy, FilesByTheirExtensionWhateverTheCase) {
    const auto folder = freshFolder("files");
    for (const char* name : {"ocean.nc", "brain.nii.gz", "brain.nii", "CT.NRRD", "head.nhdr", "wing.xyz"})
        std::ofstream(folder / name) << "not read";
    EXPECT_EQ(tstyles::formatNamedBy(folder / "ocean.nc"), "NetCDF");
    EXPECT_EQ(tstyles::formatNamedBy(folder / "brain.nii.gz"), "NIfTI");
    EXPECT_EQ(tstyles::formatNamedBy(folder / "brain.nii"), "NIfTI");
    EXPECT_EQ(tstyles::formatNamedBy(folder / "CT.NRRD"), "NRRD");
    EXPECT_EQ(tstyles::formatNamedBy(folder / "head.nhdr"), "NRRD");
    EXPECT_EQ(tstyles::formatNamedBy(folder / "wing.xyz"), "Plot3D");
}

TEST(FormatNamedBy, NothingForOtherFilesAndPlainFolders) {
    const auto folder = freshFolder("others");
    std::ofstream(folder / "notes.txt") << "text";
    std::ofstream(folder / "scene.json") << "{}";
    std::filesystem::create_directories(folder / "empty");
    EXPECT_EQ(tstyles::formatNamedBy(folder / "notes.txt"), "");
    EXPECT_EQ(tstyles::formatNamedBy(folder / "scene.json"), "");
    EXPECT_EQ(tstyles::formatNamedBy(folder / "empty"), "");
}

TEST(FormatNamedBy, AFolderWithAManifestIsADataset) {
    const auto folder = freshFolder("manifest");
    std::filesystem::create_directories(folder / "bounce");
    std::ofstream(folder / "bounce" / "series.json") << "{}";
    EXPECT_EQ(tstyles::formatNamedBy(folder / "bounce"), "tstyles manifest");
}

}  // namespace
