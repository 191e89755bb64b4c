// Where `tstyles animate` puts its frames: a movie file (FFmpeg's libraries) or a folder of numbered
// images. Both appear only when the last frame is in: until finish() they are written under a
// temporary name, and a sink dropped before finish() removes what it wrote.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "tstyles/image/image.h"

namespace tstyles::cli {

class FrameSink {
public:
    virtual ~FrameSink() = default;
    virtual void add(const Image& frame) = 0;
    virtual void finish() = 0;
    // "80 frames, libx264", "80 PNG frames": for the closing message.
    virtual std::string description() const = 0;
    // The rate the output plays at (a GIF stores whole-centisecond delays: 24 fps plays at 25).
    virtual double framesPerSecond() const = 0;
};

struct MovieSettings {
    int width = 512;
    int height = 512;
    int framesPerSecond = 24;
};

// A folder when `output` ends in a separator or is an existing folder; a movie file otherwise
// (.mp4, .webm, .gif). Checks before any rendering that the output can be written: InputError
// naming it otherwise.
bool isFrameFolder(const std::filesystem::path& output);
void requireWritableFrameOutput(const std::filesystem::path& output, const MovieSettings& settings);
std::unique_ptr<FrameSink> openFrameSink(const std::filesystem::path& output, const MovieSettings& settings);

// The name of frame `index` in a frames folder: frame-0000.png, ...
std::string frameFileName(int index);

}  // namespace tstyles::cli
