// Decoding a movie back into frames (libavformat, libavcodec, libswscale): to count its frames and
// check its pictures.
#include <functional>

#include "ffmpeg_handles.h"
#include "tstyles/core/errors.h"
#include "tstyles/video/video_file.h"

namespace tstyles {

using namespace video;

namespace {

// Calls `onFrame` with every decoded frame of the file's best video stream, in order.
VideoInfo decodeVideo(const std::filesystem::path& file, const std::function<void(const AVFrame&)>& onFrame) {
    quietenFfmpegLog();
    const auto fail = [&](const std::string& problem) { throwInputError(file, "", problem); };
    const auto check = [&](int code, const std::string& doing) {
        if (code < 0) fail("cannot read it as a movie (" + doing + ": " + errorText(code) + ")");
    };
    if (!std::filesystem::is_regular_file(file)) fail("no such movie file");
    AVFormatContext* opened = nullptr;
    check(avformat_open_input(&opened, file.c_str(), nullptr, nullptr), "opening");
    const InputHandle input(opened);
    check(avformat_find_stream_info(input.get(), nullptr), "reading the streams");
    const AVCodec* codec = nullptr;
    const int streamIndex = av_find_best_stream(input.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
    check(streamIndex, "finding a video stream");
    const AVStream& stream = *input->streams[streamIndex];
    const CodecContextHandle context(avcodec_alloc_context3(codec));
    check(avcodec_parameters_to_context(context.get(), stream.codecpar), "reading the codec parameters");
    check(avcodec_open2(context.get(), codec, nullptr), "opening the decoder");

    VideoInfo info;
    info.width = context->width;
    info.height = context->height;
    info.codecName = codec->name;
    const AVRational rate = stream.avg_frame_rate.num > 0 ? stream.avg_frame_rate : stream.r_frame_rate;
    info.framesPerSecond = rate.den > 0 ? av_q2d(rate) : 0.0;

    const PacketHandle packet(av_packet_alloc());
    const FrameHandle frame(av_frame_alloc());
    const auto receiveAll = [&] {
        while (true) {
            const int received = avcodec_receive_frame(context.get(), frame.get());
            if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
            check(received, "decoding frame " + std::to_string(info.frameCount));
            onFrame(*frame);
            ++info.frameCount;
        }
    };
    while (true) {
        const int read = av_read_frame(input.get(), packet.get());
        if (read == AVERROR_EOF) break;
        check(read, "reading");
        if (packet->stream_index == streamIndex) {
            const int sent = avcodec_send_packet(context.get(), packet.get());
            av_packet_unref(packet.get());
            check(sent, "decoding frame " + std::to_string(info.frameCount));
            receiveAll();
        } else {
            av_packet_unref(packet.get());
        }
    }
    check(avcodec_send_packet(context.get(), nullptr), "draining the decoder");
    receiveAll();
    if (info.frameCount == 0) fail("the movie has no frames");
    return info;
}

}  // namespace

VideoInfo probeVideo(const std::filesystem::path& file) {
    return decodeVideo(file, [](const AVFrame&) {});
}

std::vector<Image> readVideoFrames(const std::filesystem::path& file) {
    std::vector<Image> frames;
    ScalerHandle scaler;
    decodeVideo(file, [&](const AVFrame& frame) {
        scaler.reset(sws_getCachedContext(scaler.release(), frame.width, frame.height, AVPixelFormat(frame.format),
                                          frame.width, frame.height, AV_PIX_FMT_RGB24, SWS_POINT, nullptr, nullptr,
                                          nullptr));
        std::vector<std::uint8_t> rgb(std::size_t(frame.width) * std::size_t(frame.height) * 3);
        std::uint8_t* target[1] = {rgb.data()};
        const int targetStride[1] = {3 * frame.width};
        sws_scale(scaler.get(), frame.data, frame.linesize, 0, frame.height, target, targetStride);
        Image image(frame.width, frame.height);
        for (std::size_t pixel = 0; pixel < rgb.size() / 3; ++pixel) {
            for (std::size_t c = 0; c < 3; ++c) image.rgba[pixel * 4 + c] = float(rgb[pixel * 3 + c]) / 255.0f;
            image.rgba[pixel * 4 + 3] = 1.0f;
        }
        frames.push_back(std::move(image));
    });
    return frames;
}

}  // namespace tstyles
