// libav error text and logging, and checked allocation of frames and packets.
#include "ffmpeg_support.h"

#include <mutex>
#include <new>

extern "C" {
#include <libavutil/error.h>
#include <libavutil/log.h>
}

#include "tstyles/core/errors.h"

namespace tstyles::video {

void quietLibavLog() {
    static std::once_flag once;
    std::call_once(once, [] { av_log_set_level(AV_LOG_ERROR); });
}

std::string libavErrorText(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    if (av_strerror(code, text, sizeof text) < 0) return "libav error " + std::to_string(code);
    return text;
}

int checkLibav(int code, const std::filesystem::path& file, const std::string& field,
               const std::string& problem) {
    if (code < 0) throwInputError(file, field, problem + " (" + libavErrorText(code) + ")");
    return code;
}

int swsColorspaceOf(AVColorSpace colorspace) {
    switch (colorspace) {
    case AVCOL_SPC_BT709: return SWS_CS_ITU709;
    case AVCOL_SPC_FCC: return SWS_CS_FCC;
    case AVCOL_SPC_SMPTE240M: return SWS_CS_SMPTE240M;
    case AVCOL_SPC_BT2020_NCL:
    case AVCOL_SPC_BT2020_CL: return SWS_CS_BT2020;
    default: return SWS_CS_DEFAULT;
    }
}

FrameHandle allocateFrame() {
    FrameHandle frame(av_frame_alloc());
    if (!frame) throw std::bad_alloc();
    return frame;
}

PacketHandle allocatePacket() {
    PacketHandle packet(av_packet_alloc());
    if (!packet) throw std::bad_alloc();
    return packet;
}

}  // namespace tstyles::video
