// Movie formats by extension, and the checks made before a movie is rendered.
#include <algorithm>
#include <cctype>

#include "tstyles/core/errors.h"
#include "tstyles/video/video_file.h"

namespace tstyles {

std::string toString(VideoFormat format) {
    switch (format) {
        case VideoFormat::Mp4: return "MP4";
        case VideoFormat::WebM: return "WebM";
        case VideoFormat::Gif: return "GIF";
    }
    return "?";
}

std::optional<VideoFormat> videoFormatForPath(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".mp4") return VideoFormat::Mp4;
    if (extension == ".webm") return VideoFormat::WebM;
    if (extension == ".gif") return VideoFormat::Gif;
    return std::nullopt;
}

void requireWritableVideoPath(const std::filesystem::path& file, const VideoSettings& settings) {
    const std::optional<VideoFormat> format = videoFormatForPath(file);
    if (!format)
        throwInputError(file, "", "unknown movie format \"" + file.extension().string() +
                                      "\"; use .mp4, .webm or .gif, or a folder ending in / for frames");
    if (std::filesystem::is_directory(file)) throwInputError(file, "", "is a folder, not a movie file");
    const std::filesystem::path folder = std::filesystem::absolute(file).parent_path();
    if (!std::filesystem::is_directory(folder)) throwInputError(file, "", "the folder it would go into does not exist");
    if (*format != VideoFormat::Gif && (settings.width % 2 != 0 || settings.height % 2 != 0))
        throwInputError(file, "", toString(*format) + " (4:2:0 video) needs an even width and height, got " +
                                      std::to_string(settings.width) + "x" + std::to_string(settings.height));
}

}  // namespace tstyles
