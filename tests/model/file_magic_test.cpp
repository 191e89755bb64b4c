// The one sniffer of the readers (src/data/readers/file_magic.h): a file's start, shorter where the
// file is, and magic compared at an offset, never past the bytes read.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "readers/file_magic.h"

namespace tstyles {
namespace {

TEST(FileMagic, ReadsTheStartAndComparesAtAnOffset) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "tstyles_file_magic_test.bin";
    {
        std::ofstream out(file, std::ios::binary);
        out << std::string(128, '\0') << "DICM" << "rest";
    }
    const std::string start = fileStart(file, 132);
    EXPECT_EQ(start.size(), 132u);
    EXPECT_TRUE(hasMagicAt(start, 128, "DICM"));
    EXPECT_FALSE(hasMagicAt(start, 129, "DICM")) << "the magic runs past the bytes read";
    EXPECT_EQ(fileStart(file, 1000).size(), 136u) << "a short file gives what it has";
    EXPECT_TRUE(fileStart(file.string() + ".missing", 8).empty());
    EXPECT_FALSE(hasMagicAt("", 0, "NRRD000"));
    std::filesystem::remove(file);
}

}  // namespace
}  // namespace tstyles
