// readImage's memory cap: the pixels an image header announces are checked against the cap given
// before anything is allocated for them (the style image fuzz target reads under 16 MiB); a PNG
// chunk longer than the file is refused before libpng allocates what it claims. Read in a reader
// process, an image is the same to the bit.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/image/image_io.h"

namespace {

using namespace tstyles;

std::filesystem::path writtenImage() {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "tstyles-image-reading-test";
    std::filesystem::create_directories(folder);
    Image image(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) image.set(x, y, glm::vec4(float(x) / 7.0f, float(y) / 3.0f, 0.5f, 1.0f));
    const std::filesystem::path file = folder / "eight-by-four.png";
    writeImage(image, file);
    return file;
}

TEST(ImageReading, AnImageUnderTheCapIsRead) {
    // 8 x 4 RGBA: (4 file channels + 4 of ours) x 4 bytes x 32 pixels = 1024 bytes.
    const Image image = readImage(writtenImage(), 1024);
    EXPECT_EQ(image.width, 8);
    EXPECT_EQ(image.height, 4);
}

TEST(ImageReading, AnImageOverTheCapIsRefusedWithTheFigure) {
    const std::filesystem::path file = writtenImage();
    try {
        readImage(file, 1023);
        FAIL() << "an image over the cap was read";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("8 x 4 image header need 1024 bytes, more than the 1023 bytes"), std::string::npos)
            << message;
    }
}

// Found by fuzz_style_image (tests/fuzz/corpus/style_image/png-text-chunk-claims-1.2GB): a PNG of
// a few hundred bytes whose tEXt chunk says 0x49494900 bytes made libpng allocate 1.2 GB.
TEST(ImageReading, APngChunkLongerThanTheFileIsRefusedBeforeLibpngSeesIt) {
    const std::filesystem::path file = writtenImage().parent_path() / "text-chunk-claims-1.2GB.png";
    std::string bytes = "\x89PNG\r\n\x1a\n";
    bytes += std::string("\0\0\0\x0dIHDR\0\0\0\x08\0\0\0\x08\x08\x06\0\0\0\xc4\x0f\xbe\x8b", 25);
    bytes += std::string("\x49\x49\x49\x00tEXtsome text", 17);
    std::ofstream(file, std::ios::binary) << bytes;
    try {
        readImage(file);
        FAIL() << "the damaged PNG was read";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("PNG chunk 'tEXt' at byte 33: says 1229539584 bytes of data, but the file has 5 left"),
                  std::string::npos)
            << message;
    }
}

// Style images are read in a reader process (readImageIsolated): the same pixels to the bit, and
// the same error for a damaged file.
TEST(ImageReading, IsolatedReadingGivesTheSamePixelsAndErrors) {
    const std::filesystem::path file = writtenImage();
    const Image inProcess = readImage(file);
    const Image isolated = readImageIsolated(file);
    ASSERT_EQ(isolated.width, inProcess.width);
    ASSERT_EQ(isolated.height, inProcess.height);
    EXPECT_EQ(std::memcmp(isolated.rgba.data(), inProcess.rgba.data(), inProcess.rgba.size() * sizeof(float)), 0);

    const std::filesystem::path cut = file.parent_path() / "cut.png";
    std::filesystem::copy_file(file, cut, std::filesystem::copy_options::overwrite_existing);
    std::filesystem::resize_file(cut, 60);
    std::string inProcessError = "none";
    std::string isolatedError = "none";
    try {
        readImage(cut);
    } catch (const InputError& error) {
        inProcessError = error.what();
    }
    try {
        readImageIsolated(cut);
    } catch (const InputError& error) {
        isolatedError = error.what();
    }
    EXPECT_NE(inProcessError, "none");
    EXPECT_EQ(isolatedError, inProcessError);
}

}  // namespace
