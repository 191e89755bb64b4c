// Pixels through gdcm::ImageReader, which undoes the transfer syntax's compression and byte order;
// we undo the stored-bits packing (a 12-bit value in 16 bits, signed or not) and apply the rescale.
#include "dicom_pixels.h"

#include <algorithm>
#include <cstring>

#include <gdcmException.h>
#include <gdcmImageReader.h>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

std::size_t frameBytes(const DicomImageFile& image) {
    return std::size_t(image.rows) * std::size_t(image.columns) * std::size_t(image.bitsAllocated / 8);
}

// The stored bits of a raw value, sign-extended when the pixels are signed.
double storedValue(std::uint32_t raw, std::uint16_t bitsStored, bool isSigned) {
    const std::uint64_t mask = (std::uint64_t(1) << bitsStored) - 1;
    const std::uint64_t value = raw & mask;
    if (isSigned && (value >> (bitsStored - 1)) != 0) return double(std::int64_t(value) - std::int64_t(mask + 1));
    return double(value);
}

DicomPixelBuffer decodePixels(const DicomImageFile& image, std::uint64_t memoryCap) {
    const double expected = double(frameBytes(image)) * double(image.frames.size());
    requireMemory(image.file, "(7FE0,0010) PixelData", expected, memoryCap,
                  "the decoded pixels of " + std::to_string(image.frames.size()) + " frames");
    // Uncompressed pixels are in the file as they are: a file that ends before them is cut (GDCM
    // would read what is there and leave the rest as it was).
    if (!image.compressed && !image.deflated) {
        const std::uint64_t size = regularFileSize(image.file, "DICOM file");
        if (double(size) < double(image.pixelDataOffset) + expected)
            throwInputError(image.file, "(7FE0,0010) PixelData",
                            "is truncated: " + std::to_string(std::uint64_t(expected)) + " bytes of pixels from byte " +
                                std::to_string(image.pixelDataOffset) + " are needed, the file has " +
                                std::to_string(size) + " bytes");
    }
    silenceGdcm();
    gdcm::ImageReader reader;
    reader.SetFileName(image.file.c_str());
    if (!reader.Read())
        throwInputError(image.file, "(7FE0,0010) PixelData",
                        "GDCM cannot read the pixel data (truncated or damaged file, or an undecodable compression)");
    const gdcm::Image& decoded = reader.GetImage();
    const unsigned frames = decoded.GetNumberOfDimensions() >= 3 ? decoded.GetDimension(2) : 1;
    const gdcm::PixelFormat& format = decoded.GetPixelFormat();
    if (decoded.GetDimension(0) != image.columns || decoded.GetDimension(1) != image.rows ||
        frames != image.frames.size() || format.GetSamplesPerPixel() != 1 || format.GetBitsAllocated() != image.bitsAllocated ||
        double(decoded.GetBufferLength()) != expected)
        throwInputError(image.file, "(7FE0,0010) PixelData",
                        "decodes to an image unlike its header (size, frames or bits per pixel differ)");
    DicomPixelBuffer pixels;
    pixels.file = image.file;
    pixels.bytes.resize(std::size_t(expected));
    if (!decoded.GetBuffer(pixels.bytes.data()))
        throwInputError(image.file, "(7FE0,0010) PixelData", "GDCM cannot decode the pixel data (damaged or truncated)");
    pixels.bitsAllocated = format.GetBitsAllocated();
    pixels.bitsStored = std::min<std::uint16_t>(image.bitsStored, pixels.bitsAllocated);
    pixels.isSigned = image.pixelRepresentation == 1;
    return pixels;
}

}  // namespace

void requireSupportedPixels(const DicomImageFile& image) {
    const auto refuse = [&](const char* tag, const std::string& problem) {
        throwInputError(image.file, tag, problem);
    };
    if (image.samplesPerPixel != 1)
        refuse("(0028,0002) SamplesPerPixel",
               "is " + std::to_string(image.samplesPerPixel) +
                   ": colour (RGB, YBR) images are not read; a volume needs one sample per pixel");
    if (image.photometric != "MONOCHROME2" && image.photometric != "MONOCHROME1")
        refuse("(0028,0004) PhotometricInterpretation",
               "is " + image.photometric + ": only MONOCHROME1 and MONOCHROME2 (greyscale) images are read");
    if (image.bitsAllocated != 8 && image.bitsAllocated != 16 && image.bitsAllocated != 32)
        refuse("(0028,0100) BitsAllocated", "is " + std::to_string(image.bitsAllocated) + ": 8, 16 or 32 are read");
    if (image.bitsStored < 1 || image.bitsStored > image.bitsAllocated)
        refuse("(0028,0101) BitsStored", "is " + std::to_string(image.bitsStored) + ": must be from 1 to BitsAllocated (" +
                                             std::to_string(image.bitsAllocated) + ")");
    if (image.pixelRepresentation > 1)
        refuse("(0028,0103) PixelRepresentation", "is " + std::to_string(image.pixelRepresentation) + ": must be 0 or 1");
    if (image.rows < 2 || image.columns < 2)
        refuse("(0028,0010) Rows", "the image is " + std::to_string(image.columns) + " x " + std::to_string(image.rows) +
                                       ": a volume needs at least 2 pixels across and down");
}

DicomPixelBuffer readDicomPixels(const DicomImageFile& image, std::uint64_t memoryCap) {
    // GDCM throws its own exceptions on some damaged files: bad input like any other.
    try {
        return decodePixels(image, memoryCap);
    } catch (const gdcm::Exception& error) {
        throwInputError(image.file, "(7FE0,0010) PixelData",
                        std::string("GDCM cannot decode the pixel data (") + error.GetDescription() + ")");
    }
}

void decodeDicomFrame(const DicomPixelBuffer& pixels, const DicomImageFile& image, const DicomFrame& frame, float* out) {
    const std::size_t count = std::size_t(image.rows) * std::size_t(image.columns);
    const std::size_t bytesEach = pixels.bitsAllocated / 8;
    const char* start = pixels.bytes.data() + frame.frameInFile * count * bytesEach;
    for (std::size_t pixel = 0; pixel < count; ++pixel) {
        std::uint32_t raw = 0;
        if (bytesEach == 1) raw = static_cast<std::uint8_t>(start[pixel]);
        else if (bytesEach == 2) {
            std::uint16_t value;
            std::memcpy(&value, start + pixel * 2, 2);
            raw = value;
        } else std::memcpy(&raw, start + pixel * 4, 4);
        const double stored = storedValue(raw, pixels.bitsStored, pixels.isSigned);
        out[pixel] = float(stored * frame.rescaleSlope + frame.rescaleIntercept);
    }
}

}  // namespace tstyles
