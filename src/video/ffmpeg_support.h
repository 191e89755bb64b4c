// Small helpers shared by the movie writer and reader: libav's error text, a quiet log, and
// allocation of the handles in ffmpeg_handles.h with a check.
#pragma once

#include <filesystem>
#include <string>

#include "ffmpeg_handles.h"

namespace tstyles::video {

// Keeps libav from printing to stderr (only errors); our InputErrors carry what matters. Called
// by every entry point, cheap after the first time.
void quietLibavLog();

// av_strerror's text for a libav return code, e.g. "Invalid data found when processing input".
std::string libavErrorText(int code);

// Throws an InputError "file: field: problem (libav's text)" when `code` < 0; returns it otherwise.
int checkLibav(int code, const std::filesystem::path& file, const std::string& field,
               const std::string& problem);

// swscale's name (SWS_CS_*) for a YUV matrix tag; untagged means BT.601, swscale's default.
int swsColorspaceOf(AVColorSpace colorspace);

FrameHandle allocateFrame();
PacketHandle allocatePacket();

}  // namespace tstyles::video
