// Atomic writes leave either the finished file or nothing.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"

namespace {

std::filesystem::path freshFolder(const std::string& name) {
    auto folder = std::filesystem::temp_directory_path() / ("tstyles_atomic_" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

TEST(AtomicFile, WritesTheWholeText) {
    const auto folder = freshFolder("whole");
    tstyles::writeFileAtomically(folder / "a.txt", std::string_view("hello"));
    std::ifstream in(folder / "a.txt");
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "hello");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder), {}), 1);
}

TEST(AtomicFile, AFailingWriterLeavesNothingBehind) {
    const auto folder = freshFolder("failing");
    EXPECT_THROW(tstyles::writeAtomically(folder / "b.png",
                                          [](const std::filesystem::path& temporary) {
                                              std::ofstream(temporary) << "half";
                                              throw std::runtime_error("writer failed");
                                          }),
                 std::runtime_error);
    EXPECT_TRUE(std::filesystem::is_empty(folder));
}

TEST(AtomicFile, AMissingFolderIsAnInputErrorNamingTheFile) {
    const auto target = freshFolder("missing") / "no" / "such" / "c.txt";
    try {
        tstyles::writeFileAtomically(target, std::string_view("x"));
        FAIL() << "expected an InputError";
    } catch (const tstyles::InputError& error) {
        EXPECT_NE(std::string(error.what()).find(target.string()), std::string::npos) << error.what();
    }
}

TEST(InputProblem, NamesFileFieldAndProblem) {
    EXPECT_EQ(tstyles::describeInputProblem("s.json", "stf.opacity[2].at", "must be in [0,1]"),
              "s.json: stf.opacity[2].at: must be in [0,1]");
}

}  // namespace
