// Movie files of rendered frames: MP4 (H.264), WebM (VP9) and looping GIF, written and read back
// through FFmpeg. The header names no FFmpeg type, so front ends need not see libav's headers.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/image/image.h"

namespace tstyles {

enum class VideoFormat { Mp4, WebM, Gif };

std::string toString(VideoFormat format);

// By extension (.mp4, .webm, .gif, case-insensitive); none for anything else.
std::optional<VideoFormat> videoFormatForPath(const std::filesystem::path& file);

struct VideoSettings {
    int width = 512;
    int height = 512;
    int framesPerSecond = 24;
};

// The rate a movie written at `framesPerSecond` plays at. MP4 and WebM store it exactly. GIF
// stores a delay per frame in hundredths of a second, so every frame gets round(100 / fps) cs and
// the GIF plays at 100 / that: 10, 20, 25 and 50 fps are exact, 24 fps becomes 4 cs = 25 fps,
// 30 fps 3 cs = 33.3 fps. (Players treat delays under 2 cs as 10 cs, so GIFs above 50 fps are
// refused.)
double storedFramesPerSecond(VideoFormat format, int framesPerSecond);

// Checks before any rendering that a movie can be written: the folder exists, the target is not a
// folder, the extension is known, and the size and rate suit the codec (H.264 and VP9 store
// yuv420p, which needs an even width and height). InputError naming the file (and the option that
// named it, such as "-o") otherwise.
void requireWritableVideoPath(const std::filesystem::path& file, const VideoSettings& settings,
                              const std::string& option = "");

// Encodes frames one at a time into a temporary sibling of the target, renamed onto the target by
// finish(); a writer dropped without finish() leaves nothing behind.
class VideoWriter {
public:
    // Picks the codec by extension: MP4 -> libx264 (or FFmpeg's mpeg4 where libavcodec lacks it),
    // WebM -> libvpx-vp9 (or libvpx VP8), GIF -> gif with a palette per frame. InputError naming
    // the target for any failure.
    VideoWriter(std::filesystem::path target, VideoSettings settings);
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;
    // Without finish(): closes and removes the temporary file; never throws.
    ~VideoWriter();

    // `frame`: RGBA floats with premultiplied alpha, rows top to bottom, as the renderer gives
    // them. It is composited over black, clamped and rounded to 8 bits. Its size must equal the
    // settings' (InputError otherwise).
    void addFrame(const Image& frame);

    // Flushes the encoder, writes the trailer and renames the temporary file onto the target.
    void finish();

    int framesWritten() const;
    std::string codecName() const;  // the encoder's name, e.g. "libx264"

private:
    struct State;
    std::unique_ptr<State> state_;
};

struct VideoInfo {
    int width = 0;
    int height = 0;
    int frameCount = 0;            // counted by decoding every frame, not read from the header
    double framesPerSecond = 0.0;  // as the container stores it (GIF: 100 / delay in cs)
    std::string codecName;         // the stream's codec, e.g. "h264", "vp9", "gif"
};

// Decodes the whole file. InputError naming the file if it cannot be read or holds no frame.
VideoInfo probeVideo(const std::filesystem::path& file);

// Every frame decoded to RGBA (alpha 1), for tests and checks.
std::vector<Image> readVideoFrames(const std::filesystem::path& file);

}  // namespace tstyles
