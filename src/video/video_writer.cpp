// VideoWriter: frames -> encoder -> muxer -> a temporary file, renamed onto the target at the end.
#include <algorithm>
#include <stdexcept>
#include <system_error>

#include "ffmpeg_support.h"
#include "frame_pixels.h"
#include "gif_palette.h"
#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"
#include "tstyles/video/video_file.h"
#include "video_encoder.h"

namespace tstyles {

using namespace video;

struct VideoWriter::State {
    std::filesystem::path target;
    std::filesystem::path temporary;
    VideoSettings settings;
    VideoFormat format = VideoFormat::Mp4;
    OutputFormatHandle muxer;
    AVStream* stream = nullptr;  // owned by the muxer
    CodecContextHandle encoder;
    ScalerHandle rgbToYuv;  // null for GIF, whose frames are palettised instead
    FrameHandle frame;
    PacketHandle packet;
    int framesWritten = 0;
    bool headerWritten = false;
    bool finished = false;

    // Sets up muxer, stream, encoder and the frame to fill; the file is at `temporary`.
    void open();

    // Hands every packet the encoder has ready to the muxer.
    void drainEncoder() {
        for (;;) {
            const int received = avcodec_receive_packet(encoder.get(), packet.get());
            if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
            checkLibav(received, target, "", "encoding failed");
            // Each frame lasts one tick of the encoder's time base; the muxer reads the last
            // frame's length from here (GIF's last delay, MP4's duration).
            if (packet->duration <= 0) packet->duration = 1;
            av_packet_rescale_ts(packet.get(), encoder->time_base, stream->time_base);
            packet->stream_index = stream->index;
            // Takes the packet's data and leaves the packet blank for the next one.
            checkLibav(av_interleaved_write_frame(muxer.get(), packet.get()), target, "", "cannot write a frame");
        }
    }

    void fillYuv(const std::vector<std::uint8_t>& rgb) {
        const std::uint8_t* source[] = {rgb.data()};
        const int sourceStride[] = {settings.width * 3};
        sws_scale(rgbToYuv.get(), source, sourceStride, 0, settings.height, frame->data, frame->linesize);
    }

    void fillPaletted(const std::vector<std::uint8_t>& rgb) {
        const PalettedFrame paletted = palettize(rgb, settings.width, settings.height);
        for (int y = 0; y < settings.height; ++y)
            std::copy_n(paletted.indices.begin() + std::ptrdiff_t(y) * settings.width, settings.width,
                        frame->data[0] + std::ptrdiff_t(y) * frame->linesize[0]);
        std::copy(paletted.palette.begin(), paletted.palette.end(), reinterpret_cast<std::uint32_t*>(frame->data[1]));
    }
};

VideoWriter::VideoWriter(std::filesystem::path target, VideoSettings settings) : state_(std::make_unique<State>()) {
    quietLibavLog();
    requireWritableVideoPath(target, settings);
    State& s = *state_;
    s.target = std::move(target);
    s.temporary = temporarySiblingOf(s.target);
    s.settings = settings;
    s.format = *videoFormatForPath(s.target);
    try {
        s.open();
    } catch (...) {
        // The destructor does not run for a constructor that throws.
        s.muxer.reset();
        std::error_code ignored;
        std::filesystem::remove(s.temporary, ignored);
        throw;
    }
}

void VideoWriter::State::open() {
    AVFormatContext* context = nullptr;
    // The format is named, not guessed from the temporary name.
    checkLibav(avformat_alloc_output_context2(&context, nullptr, muxerName(format), temporary.c_str()), target,
               "", "cannot set up the " + toString(format) + " muxer");
    muxer.reset(context);
    encoder = openEncoder(format, settings, *muxer, target);

    stream = avformat_new_stream(muxer.get(), nullptr);
    if (!stream) throw std::bad_alloc();
    checkLibav(avcodec_parameters_from_context(stream->codecpar, encoder.get()), target, "",
               "cannot describe the stream");
    // A hint; the muxer may pick a finer time base in avformat_write_header (MP4: a multiple of
    // fps, WebM: 1 ms, GIF: 1 cs).
    stream->time_base = encoder->time_base;
    stream->avg_frame_rate = encoder->framerate;

    checkLibav(avio_open(&muxer->pb, temporary.c_str(), AVIO_FLAG_WRITE), target, "",
               "cannot open " + temporary.string() + " for writing");
    Dictionary options;
    if (format == VideoFormat::Mp4) options.set("movflags", "+faststart");  // playable while downloading
    if (format == VideoFormat::Gif) options.set("loop", "0");               // loop forever
    checkLibav(avformat_write_header(muxer.get(), options.address()), target, "",
               "cannot write the " + toString(format) + " header");
    headerWritten = true;

    frame = allocateFrame();
    frame->format = encoder->pix_fmt;
    frame->width = settings.width;
    frame->height = settings.height;
    checkLibav(av_frame_get_buffer(frame.get(), 0), target, "", "cannot allocate a frame");
    packet = allocatePacket();
    if (format != VideoFormat::Gif) {
        rgbToYuv.reset(sws_getContext(settings.width, settings.height, AV_PIX_FMT_RGB24, settings.width,
                                        settings.height, encoder->pix_fmt,
                                        SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr,
                                        nullptr));
        if (!rgbToYuv) throwInputError(target, "", "cannot set up the RGB to YUV conversion");
        // Full-range RGB in, limited-range YUV out in the matrix the encoder is tagged with.
        const int* matrix = sws_getCoefficients(swsColorspaceOf(encoder->colorspace));
        sws_setColorspaceDetails(rgbToYuv.get(), matrix, 1, matrix, 0, 0, 1 << 16, 1 << 16);
    }
}

VideoWriter::~VideoWriter() {
    if (!state_ || state_->finished) return;
    // The trailer goes into a file about to be removed, but writing it is how some muxers free
    // what they hold (FFmpeg 5.1's GIF muxer keeps the last packet until then). Its error, if
    // any, does not matter. Close the file before removing it; nothing here throws.
    if (state_->headerWritten) av_write_trailer(state_->muxer.get());
    state_->muxer.reset();
    std::error_code ignored;
    std::filesystem::remove(state_->temporary, ignored);
}

void VideoWriter::addFrame(const Image& image) {
    State& s = *state_;
    if (s.finished) throw std::logic_error("VideoWriter::addFrame after finish()");
    if (image.width != s.settings.width || image.height != s.settings.height)
        throwInputError(s.target, "frame " + std::to_string(s.framesWritten + 1),
                        std::to_string(image.width) + "x" + std::to_string(image.height) +
                            " does not match the movie's " + std::to_string(s.settings.width) + "x" +
                            std::to_string(s.settings.height));
    // The encoder may still hold the previous frame's buffers.
    checkLibav(av_frame_make_writable(s.frame.get()), s.target, "", "cannot allocate a frame");
    const std::vector<std::uint8_t> rgb = rgb8OverBlack(image);
    if (s.rgbToYuv) s.fillYuv(rgb);
    else s.fillPaletted(rgb);
    s.frame->pts = s.framesWritten;
    checkLibav(avcodec_send_frame(s.encoder.get(), s.frame.get()), s.target,
               "frame " + std::to_string(s.framesWritten + 1), "the encoder refused it");
    s.drainEncoder();
    ++s.framesWritten;
}

void VideoWriter::finish() {
    State& s = *state_;
    if (s.finished) throw std::logic_error("VideoWriter::finish called twice");
    if (s.framesWritten == 0) throwInputError(s.target, "", "no frames to write");
    checkLibav(avcodec_send_frame(s.encoder.get(), nullptr), s.target, "", "cannot flush the encoder");
    s.drainEncoder();
    checkLibav(av_write_trailer(s.muxer.get()), s.target, "", "cannot finish the movie");
    checkLibav(avio_closep(&s.muxer->pb), s.target, "", "cannot close " + s.temporary.string());
    std::error_code error;
    std::filesystem::rename(s.temporary, s.target, error);
    if (error) throwInputError(s.target, "", "cannot rename the finished movie into place: " + error.message());
    s.finished = true;
}

int VideoWriter::framesWritten() const { return state_->framesWritten; }

std::string VideoWriter::codecName() const { return state_->encoder->codec->name; }

}  // namespace tstyles
