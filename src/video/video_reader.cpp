// Reading movies back: every frame decoded, for probeVideo's counts and readVideoFrames' pixels.
#include <cmath>
#include <functional>

extern "C" {
#include <libavutil/pixdesc.h>
}

#include "ffmpeg_support.h"
#include "frame_pixels.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/video/video_file.h"

namespace tstyles {

using namespace video;

namespace {

// A movie file opened with the decoder of its best video stream.
struct OpenedMovie {
    InputFormatHandle demuxer;
    AVStream* stream = nullptr;  // owned by the demuxer
    CodecContextHandle decoder;
};

OpenedMovie openMovie(const std::filesystem::path& file) {
    quietLibavLog();
    if (userPathKind({}, file) == PathKind::Missing) throwInputError(file, "", "no such file");
    OpenedMovie movie;
    AVFormatContext* demuxer = nullptr;
    // On failure avformat_open_input frees the context itself.
    checkLibav(avformat_open_input(&demuxer, file.c_str(), nullptr, nullptr), file, "", "cannot read as a movie");
    movie.demuxer.reset(demuxer);
    checkLibav(avformat_find_stream_info(demuxer, nullptr), file, "", "cannot read the streams");
    const AVCodec* codec = nullptr;
    const int index = av_find_best_stream(demuxer, AVMEDIA_TYPE_VIDEO, -1, -1, &codec, 0);
    checkLibav(index, file, "", "no video stream that this FFmpeg can decode");
    movie.stream = demuxer->streams[index];
    movie.decoder.reset(avcodec_alloc_context3(codec));
    if (!movie.decoder) throw std::bad_alloc();
    checkLibav(avcodec_parameters_to_context(movie.decoder.get(), movie.stream->codecpar), file, "",
               "cannot describe the video stream");
    checkLibav(avcodec_open2(movie.decoder.get(), codec, nullptr), file, "",
               std::string("cannot open the ") + codec->name + " decoder");
    return movie;
}

// The rate the container states: its average frame rate (MP4: frames over duration; WebM: the
// default frame duration; GIF: 100 / delay), else the demuxer's guess from the first timestamps.
double storedFrameRate(const AVStream& stream) {
    for (const AVRational rate : {stream.avg_frame_rate, stream.r_frame_rate})
        if (rate.num > 0 && rate.den > 0) return av_q2d(rate);
    return 0.0;
}

// Demuxers stop quietly at the end of a file cut short, so the frames decoded are compared with
// what the header promises: a frame count (MP4, and GIF as counted by the demuxer) or else a
// duration at the stored rate (WebM writes its duration into the header when it is finished).
void requireWholeMovie(const OpenedMovie& movie, const std::filesystem::path& file, int frames) {
    std::int64_t promised = movie.stream->nb_frames;
    if (promised <= 0 && movie.demuxer->duration > 0)
        promised = std::llround(double(movie.demuxer->duration) / AV_TIME_BASE * storedFrameRate(*movie.stream));
    if (promised > frames)
        throwInputError(file, "", "promises " + std::to_string(promised) + " frames but only " +
                                      std::to_string(frames) + " could be decoded (is the file cut short?)");
}

// Decodes every frame of the video stream in order, flushing the decoder at the end of the file.
// Returns the number of frames. Read and decode errors are InputErrors naming the file.
int decodeAll(OpenedMovie& movie, const std::filesystem::path& file, const std::function<void(const AVFrame&)>& use) {
    PacketHandle packet = allocatePacket();
    FrameHandle frame = allocateFrame();
    int frames = 0;
    const auto receiveFrames = [&] {
        for (;;) {
            const int received = avcodec_receive_frame(movie.decoder.get(), frame.get());
            if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
            checkLibav(received, file, "frame " + std::to_string(frames + 1), "cannot decode");
            use(*frame);
            ++frames;
            av_frame_unref(frame.get());
        }
    };
    for (;;) {
        const int read = av_read_frame(movie.demuxer.get(), packet.get());
        if (read == AVERROR_EOF) break;
        checkLibav(read, file, "frame " + std::to_string(frames + 1), "cannot read");
        if (packet->stream_index == movie.stream->index) {
            const int sent = avcodec_send_packet(movie.decoder.get(), packet.get());
            av_packet_unref(packet.get());
            checkLibav(sent, file, "frame " + std::to_string(frames + 1), "cannot decode");
            receiveFrames();
        } else {
            av_packet_unref(packet.get());
        }
    }
    checkLibav(avcodec_send_packet(movie.decoder.get(), nullptr), file, "", "cannot flush the decoder");
    receiveFrames();
    if (frames == 0) throwInputError(file, "", "holds no video frame");
    requireWholeMovie(movie, file, frames);
    return frames;
}

bool isYuv(AVPixelFormat format) {
    const AVPixFmtDescriptor* descriptor = av_pix_fmt_desc_get(format);
    return descriptor && !(descriptor->flags & (AV_PIX_FMT_FLAG_RGB | AV_PIX_FMT_FLAG_PAL)) && descriptor->nb_components >= 3;
}

// Converts decoded frames of any pixel format to RGBA images, one scaler reused while the
// frames' size and format stay the same.
class RgbaConverter {
public:
    // `stream`'s colour tags (from the container) stand in for frames whose bitstream has none (VP8).
    RgbaConverter(std::filesystem::path file, const AVCodecParameters& stream)
        : file_(std::move(file)), streamColorspace_(stream.color_space), streamRange_(stream.color_range) {}

    Image operator()(const AVFrame& frame) {
        const auto format = AVPixelFormat(frame.format);
        scaler_.reset(sws_getCachedContext(scaler_.release(), frame.width, frame.height, format, frame.width,
                                           frame.height, AV_PIX_FMT_RGBA,
                                           SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr,
                                           nullptr));
        if (!scaler_)
            throwInputError(file_, "", std::string("cannot convert frames of pixel format ") +
                                           (av_get_pix_fmt_name(format) ? av_get_pix_fmt_name(format) : "unknown"));
        if (isYuv(format)) {
            const AVColorSpace colorspace =
                frame.colorspace != AVCOL_SPC_UNSPECIFIED ? frame.colorspace : streamColorspace_;
            const AVColorRange range =
                frame.color_range != AVCOL_RANGE_UNSPECIFIED ? frame.color_range : streamRange_;
            const int* coefficients = sws_getCoefficients(swsColorspaceOf(colorspace));
            const int fullRange = range == AVCOL_RANGE_JPEG ? 1 : 0;
            sws_setColorspaceDetails(scaler_.get(), coefficients, fullRange, coefficients, 1, 0, 1 << 16, 1 << 16);
        }
        rgba_.resize(std::size_t(frame.width) * std::size_t(frame.height) * 4);
        std::uint8_t* destination[] = {rgba_.data()};
        const int destinationStride[] = {frame.width * 4};
        sws_scale(scaler_.get(), frame.data, frame.linesize, 0, frame.height, destination, destinationStride);
        return imageFromRgba8(rgba_.data(), frame.width * 4, frame.width, frame.height);
    }

private:
    std::filesystem::path file_;
    AVColorSpace streamColorspace_;
    AVColorRange streamRange_;
    ScalerHandle scaler_;
    std::vector<std::uint8_t> rgba_;
};

}  // namespace

VideoInfo probeVideo(const std::filesystem::path& file) {
    OpenedMovie movie = openMovie(file);
    VideoInfo info;
    info.width = movie.decoder->width;
    info.height = movie.decoder->height;
    info.codecName = avcodec_get_name(movie.stream->codecpar->codec_id);
    info.frameCount = decodeAll(movie, file, [](const AVFrame&) {});
    info.framesPerSecond = storedFrameRate(*movie.stream);
    return info;
}

std::vector<Image> readVideoFrames(const std::filesystem::path& file) {
    OpenedMovie movie = openMovie(file);
    RgbaConverter toImage(file, *movie.stream->codecpar);
    std::vector<Image> frames;
    decodeAll(movie, file, [&](const AVFrame& frame) { frames.push_back(toImage(frame)); });
    return frames;
}

}  // namespace tstyles
