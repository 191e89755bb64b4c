// Paths the user wrote: each refusal of the system is an InputError naming the file and the field,
// with the problem in words, never a std::filesystem_error.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"

namespace {

namespace fs = std::filesystem;
using tstyles::PathKind;
using tstyles::PathSource;

fs::path freshFolder(const std::string& name) {
    auto folder = fs::temp_directory_path() / ("tstyles_user_paths_" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

// The message of the InputError `call` throws, or a failure when it throws none.
template <typename Call>
std::string inputErrorOf(Call&& call) {
    try {
        call();
    } catch (const tstyles::InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "expected an InputError";
    return "";
}

const PathSource kStyle{"scene.json", "stf.color[2].style"};

TEST(UserPaths, ANameTooLongIsNamedWithItsLength) {
    const std::string name(5000, 'a');
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireUsablePathName(kStyle, name); }),
              "scene.json: stf.color[2].style: the name is too long for the file system (5000 characters)");
    // One name of 256 characters is over Linux's 255; 255 is allowed.
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireUsablePathName(kStyle, "styles/" + std::string(256, 'b')); }),
              "scene.json: stf.color[2].style: the name is too long for the file system (256 characters)");
    EXPECT_NO_THROW(tstyles::requireUsablePathName(kStyle, "styles/" + std::string(255, 'b')));
}

TEST(UserPaths, APathTooLongIsNamedWithItsLengthAndTheLimit) {
    std::string path;
    for (int i = 0; i < 20; ++i) path += "/" + std::string(250, 'c');  // 20 x 251 = 5020 characters
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireUsablePathName({"s.json", "dataset"}, path); }),
              "s.json: dataset: the path is too long for the file system (5020 characters, at most 4095)");
}

TEST(UserPaths, ANulInTheNameIsRefused) {
    const std::string name("bright\0.png", 11);
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireUsablePathName(kStyle, name); }),
              "scene.json: stf.color[2].style: bright: the name holds a NUL character");
}

TEST(UserPaths, KindsOfWhatIsThere) {
    const fs::path folder = freshFolder("kinds");
    std::ofstream(folder / "file.txt") << "x";
    ASSERT_EQ(::mkfifo((folder / "fifo").c_str(), 0600), 0);
    EXPECT_EQ(tstyles::userPathKind({}, folder / "file.txt"), PathKind::RegularFile);
    EXPECT_EQ(tstyles::userPathKind({}, folder), PathKind::Folder);
    EXPECT_EQ(tstyles::userPathKind({}, folder / "fifo"), PathKind::Other);
    EXPECT_EQ(tstyles::userPathKind({}, folder / "missing" / "deeper"), PathKind::Missing);
}

TEST(UserPaths, AFileUsedAsAFolderIsNamed) {
    const fs::path folder = freshFolder("not_a_folder");
    std::ofstream(folder / "file.txt") << "x";
    const fs::path inside = folder / "file.txt" / "series.json";
    EXPECT_EQ(inputErrorOf([&] { tstyles::userPathKind({"scene.json", "dataset"}, inside); }),
              "scene.json: dataset: " + inside.string() + ": a part of the path is a file, not a folder");
    // On the command line the path itself is the file named.
    EXPECT_EQ(inputErrorOf([&] { tstyles::userPathKind({"", "-o"}, inside); }),
              inside.string() + ": -o: a part of the path is a file, not a folder");
}

TEST(UserPaths, ALoopOfLinksIsNamed) {
    const fs::path folder = freshFolder("loop");
    fs::create_symlink(folder / "b", folder / "a");
    fs::create_symlink(folder / "a", folder / "b");
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireUserFile({}, folder / "a", "scene file"); }),
              (folder / "a").string() + ": a loop of symbolic links (or too many links in a row)");
}

TEST(UserPaths, ARegularFileIsRequiredWhereOneIsRead) {
    const fs::path folder = freshFolder("regular");
    ASSERT_EQ(::mkfifo((folder / "fifo.json").c_str(), 0600), 0);
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireUserFile({}, folder, "scene file"); }),
              folder.string() + ": is a folder, not a scene file");
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireUserFile({}, folder / "fifo.json", "scene file"); }),
              (folder / "fifo.json").string() +
                  ": is not a regular file (a device, FIFO or socket cannot be read as a scene file)");
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireUserFile({}, folder / "none.json", "scene file"); }),
              (folder / "none.json").string() + ": no such scene file");
}

TEST(UserPaths, AnOutputFileNeedsAFolderAndNoFolderOrFifoInItsPlace) {
    const fs::path folder = freshFolder("output");
    std::ofstream(folder / "file.txt") << "x";
    ASSERT_EQ(::mkfifo((folder / "fifo.png").c_str(), 0600), 0);
    const PathSource output{"", "-o"};
    EXPECT_NO_THROW(tstyles::requireOutputFile(output, folder / "new.png", "image file"));
    EXPECT_NO_THROW(tstyles::requireOutputFile(output, folder / "file.txt", "image file"));  // replaced
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireOutputFile(output, folder / "fifo.png", "image file"); }),
              (folder / "fifo.png").string() +
                  ": -o: is not a regular file (a FIFO, device or socket), not replaced by the image file");
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireOutputFile(output, folder, "image file"); }),
              folder.string() + ": -o: is a folder, not an image file");
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireOutputFile(output, folder / "no" / "x.png", "image file"); }),
              (folder / "no" / "x.png").string() + ": -o: the folder " + (folder / "no").string() +
                  " does not exist");
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireOutputFile(output, folder / "file.txt" / "x.png", "image file"); }),
              (folder / "file.txt" / "x.png").string() + ": -o: " + (folder / "file.txt").string() +
                  " is a file, not a folder");
}

TEST(UserPaths, AnOutputFolderMayBeNewOrAFolderButNotAFile) {
    const fs::path folder = freshFolder("output_folder");
    std::ofstream(folder / "file.txt") << "x";
    EXPECT_NO_THROW(tstyles::requireOutputFolder({}, folder / "frames", "frame folder"));
    EXPECT_NO_THROW(tstyles::requireOutputFolder({}, folder, "frame folder"));
    EXPECT_EQ(inputErrorOf([&] { tstyles::requireOutputFolder({}, folder / "file.txt", "frame folder"); }),
              (folder / "file.txt").string() + ": is a file, not a frame folder");
}

TEST(UserPaths, AFileSystemErrorBecomesTheSameInputError) {
    const fs::path folder = freshFolder("filesystem_error");
    fs::create_symlink(folder / "b", folder / "a");
    fs::create_symlink(folder / "a", folder / "b");
    EXPECT_EQ(inputErrorOf([&] {
                  tstyles::withUserPath({"suite.json", "cases[0].scene"}, folder / "a",
                                        [&] { return fs::file_size(folder / "a"); });
              }),
              "suite.json: cases[0].scene: " + (folder / "a").string() +
                  ": a loop of symbolic links (or too many links in a row)");
    const fs::path tooLong = folder / std::string(300, 'd');
    EXPECT_EQ(inputErrorOf([&] { tstyles::withUserPath({"", "-o"}, tooLong, [&] { return fs::status(tooLong); }); }),
              tooLong.string() + ": -o: the name is too long for the file system (300 characters)");
}

TEST(UserPaths, AbsolutePathsAreNormal) {
    EXPECT_EQ(tstyles::userAbsolutePath({}, "/a/b/../c/./d.json"), fs::path("/a/c/d.json"));
    EXPECT_EQ(tstyles::userAbsolutePath({}, "x.json"), fs::current_path() / "x.json");
}

}  // namespace
