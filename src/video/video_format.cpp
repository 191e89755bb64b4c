// Movie formats by extension, and the checks a front end runs before it renders any frame.
#include <cctype>

#include "tstyles/core/ascii_case.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/video/video_file.h"
#include "video_encoder.h"

namespace tstyles {

std::string toString(VideoFormat format) {
    switch (format) {
    case VideoFormat::Mp4: return "MP4";
    case VideoFormat::WebM: return "WebM";
    case VideoFormat::Gif: return "GIF";
    }
    return "unknown";
}

std::optional<VideoFormat> videoFormatForPath(const std::filesystem::path& file) {
    const std::string extension = lowercaseExtension(file);
    if (extension == ".mp4") return VideoFormat::Mp4;
    if (extension == ".webm") return VideoFormat::WebM;
    if (extension == ".gif") return VideoFormat::Gif;
    return std::nullopt;
}

double storedFramesPerSecond(VideoFormat format, int framesPerSecond) {
    if (format == VideoFormat::Gif) return 100.0 / video::gifDelayCentiseconds(framesPerSecond);
    return framesPerSecond;
}

void requireWritableVideoPath(const std::filesystem::path& file, const VideoSettings& settings,
                              const std::string& option) {
    requireOutputFile(PathSource{"", option}, file, "movie file");
    const auto format = videoFormatForPath(file);
    if (!format) throwInputError(file, option, "cannot write movies of this type; use .mp4, .webm or .gif");

    const std::string size = std::to_string(settings.width) + "x" + std::to_string(settings.height);
    if (settings.width <= 0 || settings.height <= 0)
        throwInputError(file, "size", size + " is empty; width and height must be positive");
    if (settings.framesPerSecond <= 0)
        throwInputError(file, "frame rate", std::to_string(settings.framesPerSecond) +
                                                " frames per second; the rate must be positive");
    // 4:2:0 chroma covers 2x2 pixels, so H.264 and VP9 movies need even sides.
    if (*format != VideoFormat::Gif && (settings.width % 2 != 0 || settings.height % 2 != 0))
        throwInputError(file, "size", size + " has an odd side; " + toString(*format) +
                                          " movies (yuv420p) need an even width and height");
    // GIF's 16-bit screen size; delays under 2 cs are played as 10 cs by browsers.
    if (*format == VideoFormat::Gif && (settings.width > 65535 || settings.height > 65535))
        throwInputError(file, "size", size + " is larger than a GIF can hold (65535)");
    if (*format == VideoFormat::Gif && settings.framesPerSecond > 50)
        throwInputError(file, "frame rate", std::to_string(settings.framesPerSecond) +
                                                " frames per second is too fast for a GIF (at most 50: "
                                                "players slow shorter delays down to 1/10 s)");
}

}  // namespace tstyles
