// Movie files through FFmpeg's libraries (libavcodec, libavformat, libswscale): MP4 (H.264), WebM
// (VP9) and GIF, written frame by frame under a temporary name and renamed when finished, and read
// back frame by frame (for checks and tests).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/image/image.h"

namespace tstyles {

enum class VideoFormat { Mp4, WebM, Gif };
std::string toString(VideoFormat format);  // "MP4", "WebM", "GIF"
// By extension (.mp4, .webm, .gif, any case); none for anything else.
std::optional<VideoFormat> videoFormatForPath(const std::filesystem::path& file);

struct VideoSettings {
    int width = 512;
    int height = 512;
    int framesPerSecond = 24;
};

// Checks before any rendering that the movie can be written: its folder exists, it is not a
// folder, the extension is known, and the size suits the codec (H.264 and VP9 in 4:2:0 need even
// sides). InputError naming the file otherwise.
void requireWritableVideoPath(const std::filesystem::path& file, const VideoSettings& settings);

class VideoWriter {
public:
    // Opens a temporary sibling of `target` with the codec of its format: H.264 (libx264; the
    // built-in MPEG-4 part 2 encoder where libavcodec has no libx264), VP9 (libvpx; else VP8),
    // GIF with a palette per frame. InputError naming `target` on failure.
    VideoWriter(const std::filesystem::path& target, const VideoSettings& settings);
    ~VideoWriter();  // without finish(): the temporary file is removed
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    // A frame of the settings' size (RGBA, premultiplied), composited over black.
    void addFrame(const Image& frame);
    // Drains the encoder, writes the trailer and renames the file into place.
    void finish();
    int framesWritten() const;
    std::string codecName() const;

private:
    class Encoder;
    std::unique_ptr<Encoder> encoder_;
};

struct VideoInfo {
    int width = 0;
    int height = 0;
    int frameCount = 0;  // counted by decoding every frame
    double framesPerSecond = 0.0;
    std::string codecName;
};
VideoInfo probeVideo(const std::filesystem::path& file);
// Every frame as RGBA with alpha 1.
std::vector<Image> readVideoFrames(const std::filesystem::path& file);

}  // namespace tstyles
