// The one rule that says where the bundled data is read from: environment, installed prefix, source tree.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tstyles/core/bundled_data.h"

namespace {

using tstyles::chooseDataDirectory;
using tstyles::DataDirectorySource;

// A fake prefix: PREFIX/bin/tstyles, PREFIX/lib/python3/dist-packages/tstyles/_native.so and, with
// `withData`, PREFIX/share/tstyles/.
std::filesystem::path fakePrefix(const std::string& name, bool withData) {
    const auto prefix = std::filesystem::temp_directory_path() / ("tstyles_bundled_data_" + name);
    std::filesystem::remove_all(prefix);
    std::filesystem::create_directories(prefix / "bin");
    std::filesystem::create_directories(prefix / "lib/python3/dist-packages/tstyles");
    std::ofstream(prefix / "bin/tstyles") << "";
    std::ofstream(prefix / "lib/python3/dist-packages/tstyles/_native.so") << "";
    if (withData) std::filesystem::create_directories(prefix / "share/tstyles");
    return prefix;
}

TEST(BundledData, TheEnvironmentComesFirst) {
    const auto prefix = fakePrefix("environment", true);
    const auto choice = chooseDataDirectory("/somewhere/data", prefix / "bin/tstyles", "/source/data");
    EXPECT_EQ(choice.directory, "/somewhere/data");
    EXPECT_EQ(choice.source, DataDirectorySource::Environment);
}

TEST(BundledData, AnEmptyEnvironmentValueIsUnset) {
    const auto prefix = fakePrefix("empty_environment", true);
    const auto choice = chooseDataDirectory("", prefix / "bin/tstyles", "/source/data");
    EXPECT_EQ(choice.directory, prefix / "share/tstyles");
    EXPECT_EQ(choice.source, DataDirectorySource::Installed);
}

TEST(BundledData, TheExecutableFindsShareBesideItsBin) {
    const auto prefix = fakePrefix("executable", true);
    const auto choice = chooseDataDirectory(nullptr, prefix / "bin/tstyles", "/source/data");
    EXPECT_EQ(choice.directory, prefix / "share/tstyles");
    EXPECT_EQ(choice.source, DataDirectorySource::Installed);
}

TEST(BundledData, ThePythonModuleFindsShareFourFoldersUp) {
    const auto prefix = fakePrefix("module", true);
    const auto choice =
        chooseDataDirectory(nullptr, prefix / "lib/python3/dist-packages/tstyles/_native.so", "/source/data");
    EXPECT_EQ(choice.directory, prefix / "share/tstyles");
    EXPECT_EQ(choice.source, DataDirectorySource::Installed);
}

TEST(BundledData, ARelocatedPrefixFindsItsOwnData) {
    const auto original = fakePrefix("original", true);
    const auto moved = std::filesystem::temp_directory_path() / "tstyles_bundled_data_moved";
    std::filesystem::remove_all(moved);
    std::filesystem::rename(original, moved);
    const auto choice = chooseDataDirectory(nullptr, moved / "bin/tstyles", "/source/data");
    EXPECT_EQ(choice.directory, moved / "share/tstyles");
}

TEST(BundledData, WithoutAnInstalledShareTheSourceTree) {
    const auto prefix = fakePrefix("build_tree", false);
    const auto choice = chooseDataDirectory(nullptr, prefix / "bin/tstyles", "/source/data");
    EXPECT_EQ(choice.directory, "/source/data");
    EXPECT_EQ(choice.source, DataDirectorySource::SourceTree);
    EXPECT_EQ(chooseDataDirectory(nullptr, "", "/source/data").source, DataDirectorySource::SourceTree);
}

TEST(BundledData, AShareFiveFoldersUpIsNotThisPrefix) {
    const auto prefix = fakePrefix("too_deep", true);
    const auto deep = prefix / "a/b/c/d/e";
    std::filesystem::create_directories(deep);
    EXPECT_EQ(chooseDataDirectory(nullptr, deep / "tstyles", "/source/data").source, DataDirectorySource::SourceTree);
}

TEST(BundledData, ThisTestRunsFromTheBuildTree) {
    // The test executable sits in the build folder, whose prefixes hold no share/tstyles.
    EXPECT_FALSE(tstyles::runningBinary().empty());
    EXPECT_EQ(tstyles::runningBinary().filename(), "tstyles_model_tests");
}

}  // namespace
