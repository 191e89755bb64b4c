// Encoding frames into MP4, WebM or GIF with libavcodec and libavformat (send/receive API).
#include <algorithm>
#include <cmath>
#include <system_error>

extern "C" {
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
}

#include "ffmpeg_handles.h"
#include "gif_palette.h"
#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"
#include "tstyles/video/video_file.h"

namespace tstyles {

using namespace video;

namespace {

// The first encoder this libavcodec has, by name.
const AVCodec* firstEncoder(std::initializer_list<const char*> names) {
    for (const char* name : names)
        if (const AVCodec* codec = avcodec_find_encoder_by_name(name)) return codec;
    return nullptr;
}

const AVCodec* encoderFor(VideoFormat format) {
    switch (format) {
        case VideoFormat::Mp4: return firstEncoder({"libx264", "mpeg4"});
        case VideoFormat::WebM: return firstEncoder({"libvpx-vp9", "libvpx"});
        case VideoFormat::Gif: return firstEncoder({"gif"});
    }
    return nullptr;
}

// Quality settings per encoder: visually lossless H.264 (CRF 18), constant-quality VP9, and for
// the fallbacks a fixed high quality.
void tuneEncoder(AVCodecContext& context, const AVCodec& codec) {
    const std::string name = codec.name;
    if (name == "libx264") {
        av_opt_set(context.priv_data, "crf", "18", 0);
        av_opt_set(context.priv_data, "preset", "medium", 0);
    } else if (name == "libvpx-vp9" || name == "libvpx") {
        av_opt_set(context.priv_data, "crf", "24", 0);
        av_opt_set(context.priv_data, "deadline", "good", 0);
        av_opt_set(context.priv_data, "cpu-used", "4", 0);
        context.bit_rate = 0;
    } else if (name == "mpeg4") {
        context.flags |= AV_CODEC_FLAG_QSCALE;
        context.global_quality = FF_QP2LAMBDA * 2;
    }
}

}  // namespace

class VideoWriter::Encoder {
public:
    Encoder(const std::filesystem::path& target, const VideoSettings& settings)
        : target_(target), temporary_(temporarySiblingOf(target)), settings_(settings) {
        quietenFfmpegLog();
        const std::optional<VideoFormat> format = videoFormatForPath(target);
        if (!format) throwInputError(target, "", "unknown movie format; use .mp4, .webm or .gif");
        format_ = *format;
        open();
    }

    ~Encoder() {
        if (finished_) return;
        output_.reset();  // closes the file before it is removed
        std::error_code ignored;
        std::filesystem::remove(temporary_, ignored);
    }

    void add(const Image& image) {
        if (image.width != settings_.width || image.height != settings_.height)
            fail("a frame of " + std::to_string(image.width) + "x" + std::to_string(image.height) + " in a movie of " +
                 std::to_string(settings_.width) + "x" + std::to_string(settings_.height));
        const std::vector<std::uint8_t> rgb = rgbOverBlack(image);
        check(av_frame_make_writable(frame_.get()), "preparing a frame");
        if (format_ == VideoFormat::Gif) {
            const PalettedFrame paletted = paletteFrame(rgb, image.width, image.height);
            for (int y = 0; y < image.height; ++y)
                std::copy_n(paletted.indices.begin() + std::ptrdiff_t(y) * image.width, image.width,
                            frame_->data[0] + std::ptrdiff_t(y) * frame_->linesize[0]);
            std::copy(paletted.palette.begin(), paletted.palette.end(), reinterpret_cast<std::uint32_t*>(frame_->data[1]));
        } else {
            const std::uint8_t* source[1] = {rgb.data()};
            const int sourceStride[1] = {3 * image.width};
            sws_scale(scaler_.get(), source, sourceStride, 0, image.height, frame_->data, frame_->linesize);
        }
        frame_->pts = frames_++;
        send(frame_.get());
    }

    void finish() {
        send(nullptr);
        check(av_write_trailer(output_.get()), "writing the end of the file");
        output_.reset();
        std::error_code error;
        std::filesystem::rename(temporary_, target_, error);
        if (error) fail("cannot move the finished movie into place: " + error.message());
        finished_ = true;
    }

    int frames() const { return int(frames_); }
    std::string codec() const { return codecName_; }

private:
    [[noreturn]] void fail(const std::string& problem) const { throwInputError(target_, "", problem); }
    void check(int code, const std::string& doing) const {
        if (code < 0) fail(doing + " failed: " + errorText(code));
    }

    void open() {
        const AVCodec* codec = encoderFor(format_);
        if (!codec) fail("this FFmpeg (libavcodec) has no encoder for " + toString(format_));
        codecName_ = codec->name;
        AVFormatContext* output = nullptr;
        check(avformat_alloc_output_context2(&output, nullptr, nullptr, temporary_.c_str()), "choosing the container");
        output_.reset(output);
        stream_ = avformat_new_stream(output, nullptr);
        if (!stream_) fail("cannot add a video stream");
        context_.reset(avcodec_alloc_context3(codec));
        AVCodecContext& context = *context_;
        context.width = settings_.width;
        context.height = settings_.height;
        context.time_base = AVRational{1, settings_.framesPerSecond};
        context.framerate = AVRational{settings_.framesPerSecond, 1};
        context.pix_fmt = format_ == VideoFormat::Gif ? AV_PIX_FMT_PAL8 : AV_PIX_FMT_YUV420P;
        context.gop_size = std::max(settings_.framesPerSecond, 1);
        if (output->oformat->flags & AVFMT_GLOBALHEADER) context.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        tuneEncoder(context, *codec);
        check(avcodec_open2(&context, codec, nullptr), "opening the " + codecName_ + " encoder");
        check(avcodec_parameters_from_context(stream_->codecpar, &context), "describing the stream");
        stream_->time_base = context.time_base;
        stream_->avg_frame_rate = context.framerate;
        check(avio_open(&output->pb, temporary_.c_str(), AVIO_FLAG_WRITE), "creating " + temporary_.string());
        AVDictionary* options = nullptr;
        if (format_ == VideoFormat::Gif) av_dict_set(&options, "loop", "0", 0);  // loop forever
        const int written = avformat_write_header(output, &options);
        av_dict_free(&options);
        check(written, "writing the file header");

        frame_.reset(av_frame_alloc());
        packet_.reset(av_packet_alloc());
        frame_->format = context.pix_fmt;
        frame_->width = context.width;
        frame_->height = context.height;
        check(av_frame_get_buffer(frame_.get(), 0), "allocating a frame");
        if (format_ != VideoFormat::Gif)
            scaler_.reset(sws_getContext(context.width, context.height, AV_PIX_FMT_RGB24, context.width,
                                         context.height, context.pix_fmt, SWS_BICUBIC, nullptr, nullptr, nullptr));
        if (format_ != VideoFormat::Gif && !scaler_) fail("cannot convert RGB to " + std::string(av_get_pix_fmt_name(context.pix_fmt)));
    }

    // Premultiplied RGBA over black is just the colour channels, clamped and rounded.
    static std::vector<std::uint8_t> rgbOverBlack(const Image& image) {
        std::vector<std::uint8_t> rgb(std::size_t(image.width) * std::size_t(image.height) * 3);
        for (std::size_t pixel = 0; pixel < rgb.size() / 3; ++pixel)
            for (std::size_t c = 0; c < 3; ++c)
                rgb[pixel * 3 + c] = std::uint8_t(std::lround(std::clamp(image.rgba[pixel * 4 + c], 0.0f, 1.0f) * 255.0f));
        return rgb;
    }

    // One frame in (or none, to drain), every packet the encoder has ready out to the file.
    void send(const AVFrame* frame) {
        check(avcodec_send_frame(context_.get(), frame), "encoding frame " + std::to_string(frames_));
        while (true) {
            const int received = avcodec_receive_packet(context_.get(), packet_.get());
            if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
            check(received, "encoding");
            av_packet_rescale_ts(packet_.get(), context_->time_base, stream_->time_base);
            packet_->stream_index = stream_->index;
            check(av_interleaved_write_frame(output_.get(), packet_.get()), "writing a frame");
        }
    }

    std::filesystem::path target_;
    std::filesystem::path temporary_;
    VideoSettings settings_;
    VideoFormat format_ = VideoFormat::Mp4;
    std::string codecName_;
    OutputHandle output_;
    AVStream* stream_ = nullptr;  // owned by output_
    CodecContextHandle context_;
    FrameHandle frame_;
    PacketHandle packet_;
    ScalerHandle scaler_;
    std::int64_t frames_ = 0;
    bool finished_ = false;
};

VideoWriter::VideoWriter(const std::filesystem::path& target, const VideoSettings& settings)
    : encoder_(std::make_unique<Encoder>(target, settings)) {}
VideoWriter::~VideoWriter() = default;
void VideoWriter::addFrame(const Image& frame) { encoder_->add(frame); }
void VideoWriter::finish() { encoder_->finish(); }
int VideoWriter::framesWritten() const { return encoder_->frames(); }
std::string VideoWriter::codecName() const { return encoder_->codec(); }

}  // namespace tstyles
