// Movies written and decoded back: frame count, size and rate exact, pictures within a stated
// tolerance (exact for GIF frames of few colours), nothing left behind by an unfinished writer, and
// bad paths and files refused with the file named.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/video/video_file.h"

namespace {

using namespace tstyles;
namespace fs = std::filesystem;

fs::path freshFolder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / ("tstyles_video_" + name);
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

const glm::vec3 kColours[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1},
                              {1, 1, 1}, {0.5f, 0.5f, 0.5f}, {1, 0.5f, 0}, {0, 0.5f, 1}, {0.2f, 0.8f, 0.4f}, {0, 0, 0}};

// Frame k: flat colour k on the left half, its complement on the right.
Image testFrame(int k, int width, int height) {
    Image image(width, height);
    const glm::vec3 colour = kColours[k % 12];
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.set(x, y, glm::vec4(x < width / 2 ? colour : 1.0f - colour, 1.0f));
    return image;
}

void writeMovie(const fs::path& file, int frames, const VideoSettings& settings) {
    VideoWriter writer(file, settings);
    for (int k = 0; k < frames; ++k) writer.addFrame(testFrame(k, settings.width, settings.height));
    writer.finish();
    EXPECT_EQ(writer.framesWritten(), frames);
}

struct FormatCase {
    const char* extension;
    int framesPerSecond;
    // Largest difference per channel at a half's centre, in 1/255: H.264 and VP9 in 4:2:0 store
    // colour at half resolution and quantise, so a saturated flat colour comes back a few levels off;
    // a GIF frame of two colours keeps them exactly.
    float tolerance;
};

class VideoRoundTrip : public testing::TestWithParam<FormatCase> {};

TEST_P(VideoRoundTrip, DecodesToTheFramesSizeRateAndColoursWritten) {
    const FormatCase format = GetParam();
    const fs::path file = freshFolder(format.extension) / (std::string("movie.") + format.extension);
    const VideoSettings settings{64, 48, format.framesPerSecond};
    writeMovie(file, 12, settings);
    const VideoInfo info = probeVideo(file);
    EXPECT_EQ(info.width, 64);
    EXPECT_EQ(info.height, 48);
    EXPECT_EQ(info.frameCount, 12);
    EXPECT_DOUBLE_EQ(info.framesPerSecond, double(format.framesPerSecond));
    const std::vector<Image> frames = readVideoFrames(file);
    ASSERT_EQ(frames.size(), 12u);
    for (int k = 0; k < 12; ++k) {
        const Image expected = testFrame(k, 64, 48);
        for (const int x : {16, 48})
            for (int c = 0; c < 3; ++c)
                // The 8-bit level written, plus the stated tolerance (and float rounding).
                EXPECT_NEAR(frames[std::size_t(k)].at(x, 24)[c], std::round(expected.at(x, 24)[c] * 255.0f) / 255.0f,
                            format.tolerance / 255.0f + 1e-6f)
                    << format.extension << " frame " << k << " x " << x << " channel " << c;
    }
}

INSTANTIATE_TEST_SUITE_P(Formats, VideoRoundTrip,
                         testing::Values(FormatCase{"mp4", 25, 8.0f}, FormatCase{"webm", 25, 8.0f},
                                         FormatCase{"gif", 10, 0.0f}),
                         [](const testing::TestParamInfo<FormatCase>& test) { return std::string(test.param.extension); });

TEST(VideoGif, ManyColoursGetAMedianCutPaletteCloseToThem) {
    const fs::path file = freshFolder("gradient") / "gradient.gif";
    Image ramp(128, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 128; ++x) ramp.set(x, y, {x / 127.0f, y / 63.0f, 0.5f, 1.0f});
    VideoWriter writer(file, {128, 64, 10});
    writer.addFrame(ramp);
    writer.finish();
    const Image decoded = readVideoFrames(file).at(0);
    // 8192 colours into 256 entries: each is within a 16-level cell of the 5-bit histogram at worst.
    float worst = 0.0f;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 128; ++x)
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(decoded.at(x, y)[c] - ramp.at(x, y)[c]));
    EXPECT_LT(worst, 16.0f / 255.0f);
}

TEST(VideoWriterCleanUp, AnUnfinishedMovieLeavesNothing) {
    const fs::path folder = freshFolder("unfinished");
    {
        VideoWriter writer(folder / "movie.mp4", {64, 48, 24});
        writer.addFrame(testFrame(0, 64, 48));
    }
    EXPECT_TRUE(fs::is_empty(folder));
}

std::string errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no InputError";
    return {};
}

TEST(VideoErrors, BadPathsSizesAndFilesNameTheFile) {
    const fs::path folder = freshFolder("errors");
    EXPECT_NE(errorOf([&] { requireWritableVideoPath(folder / "movie.avi", {64, 48, 24}); })
                  .find("movie.avi: unknown movie format \".avi\""),
              std::string::npos);
    EXPECT_NE(errorOf([&] { requireWritableVideoPath(folder / "no" / "movie.mp4", {64, 48, 24}); })
                  .find("the folder it would go into does not exist"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { requireWritableVideoPath(folder / "movie.mp4", {63, 48, 24}); })
                  .find("movie.mp4: MP4 (4:2:0 video) needs an even width and height, got 63x48"),
              std::string::npos);
    EXPECT_NO_THROW(requireWritableVideoPath(folder / "movie.gif", {63, 47, 24}));
    EXPECT_NE(errorOf([&] {
                  VideoWriter writer(folder / "sized.mp4", {64, 48, 24});
                  writer.addFrame(testFrame(0, 32, 48));
              }).find("a frame of 32x48 in a movie of 64x48"),
              std::string::npos);

    std::ofstream(folder / "garbage.mp4") << "not a movie at all";
    EXPECT_NE(errorOf([&] { probeVideo(folder / "garbage.mp4"); }).find("garbage.mp4: cannot read it as a movie"),
              std::string::npos);
    // A good movie cut in half: what is left decodes to fewer frames or fails, never a crash.
    writeMovie(folder / "whole.webm", 12, {64, 48, 25});
    const auto size = fs::file_size(folder / "whole.webm");
    fs::copy_file(folder / "whole.webm", folder / "cut.webm");
    fs::resize_file(folder / "cut.webm", size / 2);
    try {
        EXPECT_LT(probeVideo(folder / "cut.webm").frameCount, 12);
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("cut.webm"), std::string::npos);
    }
}

}  // namespace
