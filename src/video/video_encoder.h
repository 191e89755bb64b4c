// The encoder for each movie format, with the settings that make it look right: H.264 (or MPEG-4
// Part 2) for MP4, VP9 (or VP8) for WebM, GIF for GIF.
#pragma once

#include <filesystem>

#include "ffmpeg_handles.h"
#include "tstyles/video/video_file.h"

namespace tstyles::video {

// An opened encoder whose time base is one frame (1/fps; GIF: its whole-cs delay), so frame k has pts k. `muxer` says whether the
// container wants global headers. InputError naming `target` if no encoder opens.
CodecContextHandle openEncoder(VideoFormat format, const VideoSettings& settings,
                               const AVFormatContext& muxer, const std::filesystem::path& target);

// Whole hundredths of a second per GIF frame, round(100 / fps), at least the 2 cs players honour.
int gifDelayCentiseconds(int framesPerSecond);

// The muxer's short name for a format ("mp4", "webm", "gif").
const char* muxerName(VideoFormat format);

}  // namespace tstyles::video
