// Movies written through FFmpeg and read back: sizes, frame counts, rates and colours survive
// each format; bad paths, sizes and files are InputErrors that name the file.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/video/video_file.h"

namespace {

using tstyles::Image;
using tstyles::InputError;
using tstyles::VideoSettings;
using tstyles::VideoWriter;

std::filesystem::path freshFolder(const std::string& name) {
    const auto folder = std::filesystem::path(TSTYLES_TEST_OUTPUT_DIR) / "video" / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

// Twelve distinct colours, as 8-bit values so that a lossless path must give them back exactly.
const std::vector<glm::ivec3> kColours = {
    {200, 30, 30}, {30, 200, 30},  {30, 30, 200},  {220, 220, 40}, {40, 220, 220}, {220, 40, 220},
    {128, 128, 128}, {250, 140, 20}, {90, 40, 160}, {20, 100, 60},  {240, 240, 240}, {16, 16, 16}};

Image flatFrame(int width, int height, glm::ivec3 colour) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) image.set(x, y, glm::vec4(glm::vec3(colour) / 255.0f, 1.0f));
    return image;
}

void writeFlatMovie(const std::filesystem::path& file, const VideoSettings& settings, int frames) {
    VideoWriter writer(file, settings);
    for (int k = 0; k < frames; ++k)
        writer.addFrame(flatFrame(settings.width, settings.height, kColours[std::size_t(k) % kColours.size()]));
    EXPECT_EQ(writer.framesWritten(), frames);
    writer.finish();
}

glm::ivec3 centre8(const Image& image) {
    const glm::vec4 c = image.at(image.width / 2, image.height / 2);
    return glm::ivec3(glm::round(glm::vec3(c) * 255.0f));
}

int maxChannelDifference(glm::ivec3 a, glm::ivec3 b) {
    const glm::ivec3 d = glm::abs(a - b);
    return std::max({d.r, d.g, d.b});
}

bool folderIsEmpty(const std::filesystem::path& folder) { return std::filesystem::is_empty(folder); }

std::string messageOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no InputError";
    return "";
}

// --- Formats by extension ------------------------------------------------------------------------

TEST(VideoFormat, FollowsTheExtensionInAnyCase) {
    EXPECT_EQ(tstyles::videoFormatForPath("a/b.mp4"), tstyles::VideoFormat::Mp4);
    EXPECT_EQ(tstyles::videoFormatForPath("b.WebM"), tstyles::VideoFormat::WebM);
    EXPECT_EQ(tstyles::videoFormatForPath("c.GIF"), tstyles::VideoFormat::Gif);
    EXPECT_FALSE(tstyles::videoFormatForPath("d.avi"));
    EXPECT_FALSE(tstyles::videoFormatForPath("mp4"));
    EXPECT_EQ(tstyles::toString(tstyles::VideoFormat::WebM), "WebM");
}

// --- Round trips -----------------------------------------------------------------------------------

struct RoundTrip {
    std::string file;
    int framesPerSecond;
    double storedFramesPerSecond;  // GIF: 100 / round(100 / fps)
    std::string decoder;
    // Largest channel error of a flat frame's centre, in 1/255: H.264 at CRF 18 and VP9 at CRF 24
    // round flat colours through limited-range BT.709 YUV (about 1/255 each way) and quantise
    // the DC of each block; 6/255 leaves room for both (measured: 1/255, also with the mpeg4 and
    // VP8 fallbacks). GIF keeps <= 256 colours exactly: 0.
    int tolerance;
};

class VideoRoundTrip : public ::testing::TestWithParam<RoundTrip> {};

TEST_P(VideoRoundTrip, GivesBackSizeCountRateAndColours) {
    const RoundTrip& p = GetParam();
    const auto file = freshFolder("round_trip_" + std::to_string(p.framesPerSecond) + "_" + p.file) / p.file;
    const VideoSettings settings{64, 48, p.framesPerSecond};
    writeFlatMovie(file, settings, 12);

    const tstyles::VideoInfo info = tstyles::probeVideo(file);
    EXPECT_EQ(info.width, 64);
    EXPECT_EQ(info.height, 48);
    EXPECT_EQ(info.frameCount, 12);
    EXPECT_EQ(info.framesPerSecond, p.storedFramesPerSecond);
    EXPECT_EQ(tstyles::storedFramesPerSecond(*tstyles::videoFormatForPath(file), p.framesPerSecond),
              p.storedFramesPerSecond);
    EXPECT_EQ(info.codecName, p.decoder);

    const std::vector<Image> frames = tstyles::readVideoFrames(file);
    ASSERT_EQ(frames.size(), 12u);
    for (std::size_t k = 0; k < frames.size(); ++k) {
        EXPECT_EQ(frames[k].width, 64);
        EXPECT_EQ(frames[k].at(32, 24).a, 1.0f);
        EXPECT_LE(maxChannelDifference(centre8(frames[k]), kColours[k]), p.tolerance)
            << "frame " << k << ": centre (" << centre8(frames[k]).r << ", " << centre8(frames[k]).g << ", "
            << centre8(frames[k]).b << ")";
    }
    // Only the target is left: the temporary file was renamed onto it.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(file.parent_path()), {}), 1);
}

// GIF rates are 100 / (delay in cs): 10 (10 cs) and 25 (4 cs) are exact; 24 is stored as 4 cs.
INSTANTIATE_TEST_SUITE_P(
    Formats, VideoRoundTrip,
    ::testing::Values(RoundTrip{"flat.mp4", 25, 25.0, "h264", 6}, RoundTrip{"flat.webm", 25, 25.0, "vp9", 6},
                      RoundTrip{"flat.gif", 10, 10.0, "gif", 0}, RoundTrip{"flat.gif", 25, 25.0, "gif", 0},
                      RoundTrip{"flat.mp4", 24, 24.0, "h264", 6}, RoundTrip{"flat.webm", 24, 24.0, "vp9", 6},
                      RoundTrip{"flat.gif", 24, 25.0, "gif", 0}, RoundTrip{"flat.mp4", 30, 30.0, "h264", 6},
                      RoundTrip{"flat.webm", 30, 30.0, "vp9", 6}),
                         [](const auto& testCase) {
                             std::string name = testCase.param.file + "_" + std::to_string(testCase.param.framesPerSecond);
                             std::replace(name.begin(), name.end(), '.', '_');
                             return name;
                         });

TEST(VideoWriter, NamesItsEncoder) {
    const auto folder = freshFolder("codec_names");
    EXPECT_TRUE(VideoWriter(folder / "a.mp4", {64, 48, 10}).codecName() == "libx264" ||
                VideoWriter(folder / "a.mp4", {64, 48, 10}).codecName() == "mpeg4");
    EXPECT_TRUE(VideoWriter(folder / "a.webm", {64, 48, 10}).codecName() == "libvpx-vp9" ||
                VideoWriter(folder / "a.webm", {64, 48, 10}).codecName() == "libvpx");
    EXPECT_EQ(VideoWriter(folder / "a.gif", {64, 48, 10}).codecName(), "gif");
}

// A GIF frame's colours with premultiplied alpha are composited over black: colour (0.4, 0.2, 0.1)
// at alpha 0.5 is stored premultiplied and shows as (102, 51, 26) over black; the right half's
// out-of-range values are clamped. A left/right split keeps both colours exactly.
TEST(VideoWriter, CompositesOverBlackAndClamps) {
    const auto file = freshFolder("over_black") / "split.gif";
    Image frame(64, 48);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) frame.set(x, y, x < 32 ? glm::vec4(0.4f, 0.2f, 0.1f, 0.5f) : glm::vec4(1.5f, -0.2f, 0.5f, 1.0f));
    VideoWriter writer(file, {64, 48, 25});
    writer.addFrame(frame);
    writer.finish();
    const std::vector<Image> frames = tstyles::readVideoFrames(file);
    ASSERT_EQ(frames.size(), 1u);
    const auto at8 = [&](int x, int y) { return glm::ivec3(glm::round(glm::vec3(frames[0].at(x, y)) * 255.0f)); };
    EXPECT_EQ(at8(16, 24), glm::ivec3(102, 51, 26));
    EXPECT_EQ(at8(48, 24), glm::ivec3(255, 0, 128));
}

// A frame with more than 256 colours (a 64x48 gradient, 3072 colours) gets a median-cut palette
// and dithering. 256 boxes hold about 12 colours each (spans of some 16 levels in red and green),
// so a pixel's nearest entry is up to ~8/255 off, and dithering adds up to the error it carries;
// dithering keeps the mean small. Measured: mean 2.5/255, worst 10/255; the bounds leave room.
TEST(VideoWriter, GifPaletteOfAGradientStaysClose) {
    const auto file = freshFolder("gradient") / "gradient.gif";
    Image frame(64, 48);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) frame.set(x, y, {x * 4 / 255.0f, y * 5 / 255.0f, 128 / 255.0f, 1.0f});
    VideoWriter writer(file, {64, 48, 10});
    writer.addFrame(frame);
    writer.finish();
    const std::vector<Image> frames = tstyles::readVideoFrames(file);
    ASSERT_EQ(frames.size(), 1u);
    double sum = 0.0;
    float worst = 0.0f;
    for (std::size_t i = 0; i < frame.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const float difference = std::abs(frames[0].rgba[i] - frame.rgba[i]) * 255.0f;
        sum += difference;
        worst = std::max(worst, difference);
    }
    const double mean = sum / double(frame.rgba.size() / 4 * 3);
    EXPECT_LT(mean, 3.5);
    EXPECT_LT(worst, 24.5f);
}

// --- Nothing half-written ---------------------------------------------------------------------------

TEST(VideoWriter, WithoutFinishLeavesNothingBehind) {
    for (const char* name : {"dropped.mp4", "dropped.webm", "dropped.gif"}) {
        const auto folder = freshFolder(std::string("dropped_") + name);
        {
            VideoWriter writer(folder / name, {64, 48, 10});
            writer.addFrame(flatFrame(64, 48, kColours[0]));
            writer.addFrame(flatFrame(64, 48, kColours[1]));
            EXPECT_FALSE(folderIsEmpty(folder)) << "the temporary file is written as frames come";
        }
        EXPECT_TRUE(folderIsEmpty(folder)) << name;
    }
}

TEST(VideoWriter, AnOldMovieStaysUntilTheNewOneIsFinished) {
    const auto file = freshFolder("replaced") / "movie.gif";
    std::ofstream(file) << "the old movie";
    {
        VideoWriter writer(file, {64, 48, 10});
        writer.addFrame(flatFrame(64, 48, kColours[0]));
    }
    std::ifstream in(file);
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), {}), "the old movie");
    writeFlatMovie(file, {64, 48, 10}, 2);
    EXPECT_EQ(tstyles::probeVideo(file).frameCount, 2);
}

TEST(VideoWriter, AFrameOfTheWrongSizeIsAnInputError) {
    const auto folder = freshFolder("wrong_size");
    VideoWriter writer(folder / "a.mp4", {64, 48, 10});
    const std::string message = messageOf([&] { writer.addFrame(flatFrame(48, 64, kColours[0])); });
    EXPECT_NE(message.find("a.mp4"), std::string::npos) << message;
    EXPECT_NE(message.find("48x64"), std::string::npos) << message;
    EXPECT_EQ(writer.framesWritten(), 0);
}

TEST(VideoWriter, FinishWithoutFramesIsAnInputError) {
    const auto folder = freshFolder("no_frames");
    {
        VideoWriter writer(folder / "a.gif", {64, 48, 10});
        EXPECT_NE(messageOf([&] { writer.finish(); }).find("a.gif"), std::string::npos);
    }
    EXPECT_TRUE(folderIsEmpty(folder));
}

// --- Checks before rendering ------------------------------------------------------------------------

TEST(RequireWritableVideoPath, AcceptsTheThreeFormats) {
    const auto folder = freshFolder("writable");
    EXPECT_NO_THROW(tstyles::requireWritableVideoPath(folder / "a.mp4", {64, 48, 24}));
    EXPECT_NO_THROW(tstyles::requireWritableVideoPath(folder / "a.WEBM", {64, 48, 24}));
    EXPECT_NO_THROW(tstyles::requireWritableVideoPath(folder / "a.gif", {63, 47, 24}));  // odd is fine in GIF
}

TEST(RequireWritableVideoPath, RefusesWhatCannotBeWrittenNamingTheFile) {
    const auto folder = freshFolder("refused");
    std::filesystem::create_directories(folder / "movie.mp4");
    const struct {
        std::filesystem::path file;
        VideoSettings settings;
        std::string says;
    } cases[] = {
        {folder / "a.avi", {64, 48, 24}, ".mp4, .webm or .gif"},
        {folder / "missing" / "a.mp4", {64, 48, 24}, "does not exist"},
        {folder / "movie.mp4", {64, 48, 24}, "is a folder"},
        {folder / "odd.mp4", {65, 48, 24}, "even width and height"},
        {folder / "odd.webm", {64, 47, 24}, "even width and height"},
        {folder / "empty.mp4", {0, 48, 24}, "must be positive"},
        {folder / "still.mp4", {64, 48, 0}, "must be positive"},
        {folder / "fast.gif", {64, 48, 60}, "too fast for a GIF"},
    };
    for (const auto& c : cases) {
        const std::string message = messageOf([&] { tstyles::requireWritableVideoPath(c.file, c.settings); });
        EXPECT_NE(message.find(c.file.string()), std::string::npos) << message;
        EXPECT_NE(message.find(c.says), std::string::npos) << message;
        // The writer runs the same checks before it opens anything.
        EXPECT_THROW(VideoWriter(c.file, c.settings), InputError) << c.file;
    }
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder), {}), 1);  // only movie.mp4/
}

// --- Files that are not movies ----------------------------------------------------------------------

void expectUnreadable(const std::filesystem::path& file) {
    for (const auto& read : std::vector<std::function<void()>>{[&] { tstyles::probeVideo(file); },
                                                                [&] { tstyles::readVideoFrames(file); }}) {
        const std::string message = messageOf(read);
        EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    }
}

TEST(ProbeVideo, AMissingFileIsAnInputError) { expectUnreadable(freshFolder("missing") / "none.mp4"); }

TEST(ProbeVideo, GarbageIsAnInputError) {
    const auto file = freshFolder("garbage") / "garbage.mp4";
    std::ofstream(file, std::ios::binary) << std::string(5000, 'x') << "not a movie";
    expectUnreadable(file);
}

// Cut at several places: inside the header, and inside the frames (MP4 declares its frame count,
// so a short file is told apart from a short movie; WebM and GIF fail to decode the cut frame).
TEST(ProbeVideo, ATruncatedFileIsAnInputError) {
    const auto folder = freshFolder("truncated");
    for (const char* name : {"whole.mp4", "whole.webm", "whole.gif"}) {
        const auto whole = folder / name;
        // Noise-free but different frames, so every frame holds data to cut.
        writeFlatMovie(whole, {64, 48, 10}, 12);
        std::ifstream in(whole, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), {});
        for (const double fraction : {0.05, 0.5, 0.9}) {
            const auto cut = folder / ("cut_" + std::to_string(int(fraction * 100)) + "_" + name);
            std::ofstream(cut, std::ios::binary) << bytes.substr(0, std::size_t(double(bytes.size()) * fraction));
            SCOPED_TRACE(cut.string());
            expectUnreadable(cut);
        }
    }
}

}  // namespace
