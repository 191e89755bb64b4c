// Reading and writing images with OpenImageIO.
#include "tstyles/core/ascii_case.h"
#include "tstyles/image/image_io.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <cctype>

#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/stderr_capture.h"
#include "tstyles/core/user_paths.h"
#include "png_chunks.h"

namespace tstyles {

namespace {

// OpenImageIO gathers several lines (its own, then the plugin's); our message is one line.
std::string oneLine(std::string text) {
    while (!text.empty() && text.back() == '\n') text.pop_back();
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at))
        text.replace(at, 1, "; ");
    return text;
}

bool isFloatFormat(const std::filesystem::path& file) {
    const std::string extension = lowercaseExtension(file);
    return extension == ".exr" || extension == ".hdr";
}
}  // namespace

void requireWritableImagePath(const std::filesystem::path& file, const std::string& option) {
    requireOutputFile(PathSource{"", option}, file, "image file");
    if (!OIIO::ImageOutput::create(file.string()))
        throwInputError(file, option, "cannot write images of this type (" + OIIO::geterror() +
                                      "); use .png, .tif or .exr");
}

void writeImage(const Image& image, const std::filesystem::path& file) {
    requireWritableImagePath(file);
    // Float formats keep the renderer's 32-bit values; the others get 8 bits per channel.
    const OIIO::TypeDesc format = isFloatFormat(file) ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        auto output = OIIO::ImageOutput::create(temporary.string());
        if (!output) throwInputError(file, "", "cannot create the image writer: " + OIIO::geterror());
        OIIO::ImageSpec spec(image.width, image.height, 4, format);
        if (!output->open(temporary.string(), spec)) throwInputError(file, "", "cannot open: " + output->geterror());
        // Our pixels carry associated alpha, as OpenImageIO expects; it un-associates for PNG.
        if (!output->write_image(OIIO::TypeDesc::FLOAT, image.rgba.data()))
            throwInputError(file, "", "write failed: " + output->geterror());
        if (!output->close()) throwInputError(file, "", "cannot finish writing: " + output->geterror());
    });
}

Image readImage(const std::filesystem::path& file, std::uint64_t maxBytes) {
    // A device (/dev/zero) or FIFO would keep OpenImageIO reading forever.
    const std::uint64_t fileSize = regularFileSize(file, "image file");
    requirePngChunksInsideFile(file, fileSize);
    // libpng prints its complaints itself; they become part of our one line instead.
    const StderrCapture libraryMessages;
    const auto withLibraryText = [&](std::string message) {
        const std::string said = libraryMessages.text();
        return said.empty() || message.find(said) != std::string::npos ? message : message + " (" + said + ")";
    };
    // The reader of the format the file's name says, and no other: when that one fails,
    // ImageInput::open would try every format it knows, and some allocate what a damaged header
    // says before checking it (OpenImageIO 2.4's WebP reader took 400 MB for a 40-byte file).
    // Created from the format's name alone, so that OpenImageIO does not probe the file with the others.
    const std::string extension = file.extension().string();
    auto input = OIIO::ImageInput::create(extension.size() > 1 ? extension.substr(1) : file.string());
    if (!input) throwInputError(file, "", withLibraryText("cannot read as an image: " + oneLine(OIIO::geterror())));
    OIIO::ImageSpec openedSpec;
    if (!input->open(file.string(), openedSpec))
        throwInputError(file, "", withLibraryText("cannot read as an image: " + oneLine(input->geterror())));
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throwInputError(file, "", "the image is empty");
    // The header's size is checked before the pixels get memory: the file's float copy plus ours.
    const double pixelCount = double(spec.width) * double(spec.height);
    requireMemory(file, "", pixelCount * double(sizeof(float)) * double(spec.nchannels + 4), maxBytes,
                  "the pixels of its " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                      " image header");
    Image image(spec.width, spec.height);
    const int channels = spec.nchannels;
    std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(channels));
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        throwInputError(file, "", withLibraryText("cannot read the pixels (truncated or damaged?): " + oneLine(input->geterror())));
    for (int y = 0; y < spec.height; ++y)
        for (int x = 0; x < spec.width; ++x) {
            const float* pixel = &pixels[(std::size_t(y) * std::size_t(spec.width) + std::size_t(x)) * std::size_t(channels)];
            glm::vec4 value(pixel[0], channels > 1 ? pixel[1] : pixel[0], channels > 2 ? pixel[2] : pixel[0],
                            channels > 3 ? pixel[3] : 1.0f);
            image.set(x, y, value);
        }
    return image;
}

Image resizeImage(const Image& image, int width, int height) {
    if (image.width == width && image.height == height) return image;
    const OIIO::ImageSpec sourceSpec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
    const OIIO::ImageBuf source(sourceSpec, const_cast<float*>(image.rgba.data()));
    OIIO::ImageBuf resized(OIIO::ImageSpec(width, height, 4, OIIO::TypeDesc::FLOAT));
    if (!OIIO::ImageBufAlgo::resize(resized, source))
        throw std::runtime_error("cannot resize an image: " + resized.geterror());
    Image result(width, height);
    resized.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 4), OIIO::TypeDesc::FLOAT, result.rgba.data());
    return result;
}

}  // namespace tstyles
