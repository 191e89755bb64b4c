// Choosing and configuring the encoder of each movie format.
#include "video_encoder.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

extern "C" {
#include <libavutil/opt.h>
}

#include "ffmpeg_support.h"
#include "tstyles/core/errors.h"

namespace tstyles::video {

namespace {

// Encoders by preference: Debian's libavcodec has libx264 and libvpx, but a build without them
// still writes a playable movie with FFmpeg's own encoders.
std::vector<const char*> encoderNames(VideoFormat format) {
    switch (format) {
    case VideoFormat::Mp4: return {"libx264", "mpeg4"};
    case VideoFormat::WebM: return {"libvpx-vp9", "libvpx"};
    case VideoFormat::Gif: return {"gif"};
    }
    return {};
}

void setOption(AVCodecContext& encoder, const char* key, const char* value) {
    // Private options of the chosen encoder; one a build lacks is not worth failing over.
    av_opt_set(encoder.priv_data, key, value, 0);
}

void configureQuality(AVCodecContext& encoder, const VideoSettings& settings) {
    const std::string name = encoder.codec->name;
    if (name == "libx264") {
        // CRF 18 is near visually lossless; "medium" keeps 512x512 frames quick to encode.
        setOption(encoder, "crf", "18");
        setOption(encoder, "preset", "medium");
    } else if (name == "mpeg4") {
        // A fixed quantiser of 2, the encoder's finest useful step.
        encoder.flags |= AV_CODEC_FLAG_QSCALE;
        encoder.global_quality = FF_QP2LAMBDA * 2;
    } else if (name == "libvpx-vp9") {
        // Constant quality (bit rate 0 with a CRF); 24 of 63 is high quality. "good" with cpu-used
        // 4 is libvpx's usual speed and quality balance.
        encoder.bit_rate = 0;
        setOption(encoder, "crf", "24");
        setOption(encoder, "deadline", "good");
        setOption(encoder, "cpu-used", "4");
        setOption(encoder, "row-mt", "1");
    } else if (name == "libvpx") {
        // VP8 has no pure constant-quality mode: a CRF within a generous bit rate (2 bits per pixel).
        encoder.bit_rate = std::int64_t(settings.width) * settings.height * settings.framesPerSecond * 2;
        setOption(encoder, "crf", "8");
        setOption(encoder, "deadline", "good");
    }
}

}  // namespace

int gifDelayCentiseconds(int framesPerSecond) {
    return std::clamp(int(std::lround(100.0 / framesPerSecond)), 2, 65535);
}

const char* muxerName(VideoFormat format) {
    switch (format) {
    case VideoFormat::Mp4: return "mp4";
    case VideoFormat::WebM: return "webm";
    case VideoFormat::Gif: return "gif";
    }
    return "";
}

CodecContextHandle openEncoder(VideoFormat format, const VideoSettings& settings,
                               const AVFormatContext& muxer, const std::filesystem::path& target) {
    const AVCodec* codec = nullptr;
    std::string tried;
    for (const char* name : encoderNames(format)) {
        codec = avcodec_find_encoder_by_name(name);
        if (codec) break;
        tried += (tried.empty() ? "" : ", ") + std::string(name);
    }
    if (!codec)
        throwInputError(target, "codec", "this FFmpeg (libavcodec) has no encoder for " + toString(format) +
                                             " movies (tried " + tried + ")");

    CodecContextHandle encoder(avcodec_alloc_context3(codec));
    if (!encoder) throw std::bad_alloc();
    encoder->width = settings.width;
    encoder->height = settings.height;
    // One tick per frame, so frame k has pts k. GIF's tick is its whole-centisecond delay, so that
    // every frame gets the same delay instead of a mix of rounded ones (4, 4, 5, 4 cs for 24 fps).
    if (format == VideoFormat::Gif) {
        const int delay = gifDelayCentiseconds(settings.framesPerSecond);
        encoder->time_base = {delay, 100};
        encoder->framerate = {100, delay};
    } else {
        encoder->time_base = {1, settings.framesPerSecond};
        encoder->framerate = {settings.framesPerSecond, 1};
    }
    encoder->sample_aspect_ratio = {1, 1};
    if (format == VideoFormat::Gif) {
        encoder->pix_fmt = AV_PIX_FMT_PAL8;
    } else {
        // 4:2:0 at limited range is what every player decodes; the frames are converted with
        // BT.709's matrix and tagged so, so that players do not guess. VP8's bitstream is BT.601
        // by definition (its decoder says so whatever the container claims).
        const bool vp8 = std::string(codec->name) == "libvpx";
        encoder->pix_fmt = AV_PIX_FMT_YUV420P;
        encoder->color_range = AVCOL_RANGE_MPEG;
        encoder->colorspace = vp8 ? AVCOL_SPC_BT470BG : AVCOL_SPC_BT709;
        encoder->color_primaries = vp8 ? AVCOL_PRI_BT470BG : AVCOL_PRI_BT709;
        encoder->color_trc = AVCOL_TRC_BT709;
    }
    if (muxer.oformat->flags & AVFMT_GLOBALHEADER) encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    configureQuality(*encoder, settings);

    checkLibav(avcodec_open2(encoder.get(), codec, nullptr), target, "codec",
               std::string("cannot open the ") + codec->name + " encoder at " + std::to_string(settings.width) +
                   "x" + std::to_string(settings.height));
    return encoder;
}

}  // namespace tstyles::video
