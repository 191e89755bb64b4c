// libtiff behind a small class: pages checked once, planes decoded strip by strip or tile by tile.
// libtiff's messages go to a per-file handler (TIFFOpenOptions' client data), never to a global one
// of ours: two files read at once on two threads keep their messages apart.
#include "tiff_file.h"

#include <tiffio.h>

#include <algorithm>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {

struct TiffFile::Diagnostics {
    std::string lastError;  // libtiff's latest complaint, quoted in ours
};

namespace {

TIFF* asTiff(void* handle) { return static_cast<TIFF*>(handle); }

int collectError(TIFF*, void* userData, const char* module, const char* format, va_list arguments) {
    char text[512];
    std::vsnprintf(text, sizeof(text), format, arguments);
    auto* diagnostics = static_cast<std::string*>(userData);
    *diagnostics = (module && *module ? std::string(module) + ": " : std::string()) + text;
    return 1;  // handled: libtiff's default handler (stderr) stays quiet
}

int ignoreWarning(TIFF*, void*, const char*, const char*, va_list) {
    return 1;  // unknown tags and the like: nothing the values depend on
}

std::string pageField(std::size_t index) { return "page " + std::to_string(index); }

template <typename T>
void convertSamples(const std::uint8_t* source, std::size_t count, std::size_t stride, float* out) {
    for (std::size_t i = 0; i < count; ++i) {
        T value;
        std::memcpy(&value, source + i * stride * sizeof(T), sizeof(T));
        out[i] = float(value);
    }
}

// `count` samples `stride` samples apart, in the host's byte order, as floats.
void convertRow(const TiffPage& page, const std::uint8_t* source, std::size_t count, std::size_t stride, float* out) {
    switch (page.valueType()) {
        case ValueType::UInt8: return convertSamples<std::uint8_t>(source, count, stride, out);
        case ValueType::Int8: return convertSamples<std::int8_t>(source, count, stride, out);
        case ValueType::UInt16: return convertSamples<std::uint16_t>(source, count, stride, out);
        case ValueType::Int16: return convertSamples<std::int16_t>(source, count, stride, out);
        case ValueType::Int32: return convertSamples<std::int32_t>(source, count, stride, out);
        case ValueType::Float32: return convertSamples<float>(source, count, stride, out);
        case ValueType::Float64:
            if (page.sampleFormat == SAMPLEFORMAT_UINT) return convertSamples<std::uint32_t>(source, count, stride, out);
            return convertSamples<double>(source, count, stride, out);
    }
}

void swapSampleBytes(std::vector<std::uint8_t>& bytes, std::size_t width) {
    for (std::size_t at = 0; at + width <= bytes.size(); at += width) std::reverse(&bytes[at], &bytes[at] + width);
}

}  // namespace

ValueType TiffPage::valueType() const {
    if (sampleFormat == SAMPLEFORMAT_IEEEFP) return bitsPerSample == 32 ? ValueType::Float32 : ValueType::Float64;
    const bool isSigned = sampleFormat == SAMPLEFORMAT_INT;
    switch (bitsPerSample) {
        case 8: return isSigned ? ValueType::Int8 : ValueType::UInt8;
        case 16: return isSigned ? ValueType::Int16 : ValueType::UInt16;
        default: return isSigned ? ValueType::Int32 : ValueType::Float64;
    }
}

std::string TiffPage::sampleTypeName() const {
    const char* kind = sampleFormat == SAMPLEFORMAT_IEEEFP ? "float" : sampleFormat == SAMPLEFORMAT_INT ? "int" : "uint";
    return kind + std::to_string(bitsPerSample);
}

bool TiffPage::sameLayout(const TiffPage& other) const {
    return width == other.width && height == other.height && samplesPerPixel == other.samplesPerPixel &&
           bitsPerSample == other.bitsPerSample && sampleFormat == other.sampleFormat;
}

TiffFile::TiffFile(const std::filesystem::path& file, std::uint64_t memoryCap)
    : file_(file), memoryCap_(memoryCap), diagnostics_(std::make_unique<Diagnostics>()) {
    requireRegularFile(file, "TIFF file");
    TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetErrorHandlerExtR(options, collectError, &diagnostics_->lastError);
    TIFFOpenOptionsSetWarningHandlerExtR(options, ignoreWarning, nullptr);
    TIFFOpenOptionsSetMaxSingleMemAlloc(options, tmsize_t(std::min<std::uint64_t>(memoryCap, INT64_MAX)));
    // "m": read with ordinary reads, not a memory map, so a file cut short after opening is an
    // error libtiff reports rather than a SIGBUS.
    tiff_ = TIFFOpenExt(file.c_str(), "rm", options);
    TIFFOpenOptionsFree(options);
    if (tiff_ == nullptr) fail("", "is not a readable TIFF file");
}

TiffFile::~TiffFile() {
    if (tiff_ != nullptr) TIFFClose(asTiff(tiff_));
}

void TiffFile::fail(const std::string& field, const std::string& problem) {
    const std::string said = diagnostics_->lastError;
    throwInputError(file_, field, problem + (said.empty() ? std::string() : " (libtiff: " + said + ")"));
}

bool TiffFile::byteSwapped() const { return TIFFIsByteSwapped(asTiff(tiff_)) != 0; }

namespace {

// Refuses what is not a measured value per sample that we can decode.
void checkPage(TIFF* tiff, const TiffPage& page, const std::filesystem::path& file, std::size_t index) {
    const std::string field = pageField(index);
    if (page.width == 0 || page.height == 0) throwInputError(file, field, "has no pixels (ImageWidth or ImageLength is 0)");
    std::uint16_t photometric = PHOTOMETRIC_MINISBLACK;
    if (TIFFGetField(tiff, TIFFTAG_PHOTOMETRIC, &photometric) == 1 && photometric != PHOTOMETRIC_MINISBLACK &&
        photometric != PHOTOMETRIC_MINISWHITE && photometric != PHOTOMETRIC_RGB && photometric != PHOTOMETRIC_SEPARATED)
        throwInputError(file, field + " PhotometricInterpretation",
                        photometric == PHOTOMETRIC_PALETTE
                            ? std::string("is a palette image: its pixels are indices into a colour map, not measured values")
                            : "is " + std::to_string(photometric) +
                                  ": only grey (0, 1), RGB (2) and separated (5) samples are read as values");
    if (page.sampleFormat == SAMPLEFORMAT_COMPLEXINT || page.sampleFormat == SAMPLEFORMAT_COMPLEXIEEEFP)
        throwInputError(file, field + " SampleFormat", "complex samples are not supported");
    const bool isFloat = page.sampleFormat == SAMPLEFORMAT_IEEEFP;
    const bool integerBits = page.bitsPerSample == 8 || page.bitsPerSample == 16 || page.bitsPerSample == 32;
    if (page.sampleFormat != SAMPLEFORMAT_UINT && page.sampleFormat != SAMPLEFORMAT_INT && !isFloat)
        throwInputError(file, field + " SampleFormat", "is " + std::to_string(page.sampleFormat) + ": not a number type");
    if (isFloat ? (page.bitsPerSample != 32 && page.bitsPerSample != 64) : !integerBits)
        throwInputError(file, field + " BitsPerSample",
                        std::to_string(page.bitsPerSample) + "-bit " + (isFloat ? "float" : "integer") +
                            " samples are not supported (integers: 8, 16, 32 bits; floats: 32, 64 bits)");
    if (page.samplesPerPixel == 0) throwInputError(file, field + " SamplesPerPixel", "is 0");
    if (TIFFIsCODECConfigured(page.compression) == 0)
        throwInputError(file, field + " Compression",
                        "is " + std::to_string(page.compression) + ", a compression this libtiff cannot decode");
}

// The current directory's description (its tags as they are, not yet checked).
TiffPage describeCurrentPage(TIFF* tiff) {
    TiffPage page;
    page.ifdOffset = TIFFCurrentDirOffset(tiff);
    TIFFGetField(tiff, TIFFTAG_IMAGEWIDTH, &page.width);
    TIFFGetField(tiff, TIFFTAG_IMAGELENGTH, &page.height);
    TIFFGetFieldDefaulted(tiff, TIFFTAG_SAMPLESPERPIXEL, &page.samplesPerPixel);
    TIFFGetFieldDefaulted(tiff, TIFFTAG_BITSPERSAMPLE, &page.bitsPerSample);
    TIFFGetFieldDefaulted(tiff, TIFFTAG_SAMPLEFORMAT, &page.sampleFormat);
    std::uint16_t planar = PLANARCONFIG_CONTIG;
    TIFFGetFieldDefaulted(tiff, TIFFTAG_PLANARCONFIG, &planar);
    page.planarSeparate = planar == PLANARCONFIG_SEPARATE && page.samplesPerPixel > 1;
    page.tiled = TIFFIsTiled(tiff) != 0;
    TIFFGetFieldDefaulted(tiff, TIFFTAG_COMPRESSION, &page.compression);
    float resolution = 0.0f;
    if (TIFFGetField(tiff, TIFFTAG_XRESOLUTION, &resolution) == 1) page.xResolution = resolution;
    if (TIFFGetField(tiff, TIFFTAG_YRESOLUTION, &resolution) == 1) page.yResolution = resolution;
    TIFFGetFieldDefaulted(tiff, TIFFTAG_RESOLUTIONUNIT, &page.resolutionUnit);
    std::uint16_t subIfdCount = 0;
    std::uint64_t* subIfds = nullptr;
    if (TIFFGetField(tiff, TIFFTAG_SUBIFD, &subIfdCount, &subIfds) == 1 && subIfds != nullptr)
        page.subIfds.assign(subIfds, subIfds + subIfdCount);
    return page;
}

}  // namespace

std::vector<TiffPage> TiffFile::readPages() {
    TIFF* tiff = asTiff(tiff_);
    std::vector<TiffPage> pages;
    if (TIFFSetDirectory(tiff, 0) == 0) fail(pageField(0), "cannot be read");
    do {
        TiffPage page = describeCurrentPage(tiff);
        checkPage(tiff, page, file_, pages.size());
        pages.push_back(page);
        diagnostics_->lastError.clear();
    } while (TIFFReadDirectory(tiff) == 1);
    // The end of the chain and a damaged directory both stop the loop; only the second complains.
    if (!diagnostics_->lastError.empty()) fail(pageField(pages.size()), "cannot be read");
    return pages;
}

TiffPage TiffFile::readSubPage(const TiffPage& page, std::size_t level, std::size_t index) {
    TIFF* tiff = asTiff(tiff_);
    diagnostics_->lastError.clear();
    if (level == 0 || level > page.subIfds.size())
        fail(pageField(index) + " SubIFDs", "has no level " + std::to_string(level));
    if (TIFFSetSubDirectory(tiff, page.subIfds[level - 1]) == 0)
        fail(pageField(index) + " SubIFD " + std::to_string(level - 1), "cannot be read");
    TiffPage sub = describeCurrentPage(tiff);
    checkPage(tiff, sub, file_, index);
    sub.subIfds.clear();
    return sub;
}

std::string TiffFile::firstDescription() {
    TIFF* tiff = asTiff(tiff_);
    if (TIFFSetDirectory(tiff, 0) == 0) fail(pageField(0), "cannot be read");
    const char* description = nullptr;
    if (TIFFGetField(tiff, TIFFTAG_IMAGEDESCRIPTION, &description) != 1 || description == nullptr) return {};
    return description;
}

void TiffFile::goToPage(const TiffPage& page, std::size_t index) {
    diagnostics_->lastError.clear();
    if (TIFFSetSubDirectory(asTiff(tiff_), page.ifdOffset) == 0) fail(pageField(index), "cannot be read");
}

std::vector<std::uint8_t> TiffFile::takeBuffer(std::int64_t bytes, std::size_t index, const char* what) {
    if (bytes <= 0) fail(pageField(index), std::string("its ") + what + " size overflows");
    requireMemory(file_, pageField(index), double(bytes), memoryCap_, std::string("one ") + what);
    return std::vector<std::uint8_t>(std::size_t(bytes));
}

void TiffFile::readPlane(const TiffPage& page, std::size_t index, int channel, float* out) {
    goToPage(page, index);
    if (page.tiled) readTiles(page, index, channel, out);
    else readStrips(page, index, channel, out);
}

void TiffFile::readStrips(const TiffPage& page, std::size_t index, int channel, float* out) {
    TIFF* tiff = asTiff(tiff_);
    std::uint32_t rowsPerStrip = page.height;
    TIFFGetFieldDefaulted(tiff, TIFFTAG_ROWSPERSTRIP, &rowsPerStrip);
    rowsPerStrip = std::clamp<std::uint32_t>(rowsPerStrip, 1, page.height);
    const std::size_t sampleBytes = page.bitsPerSample / 8;
    const std::size_t stride = page.planarSeparate ? 1 : page.samplesPerPixel;
    const std::size_t rowBytes = std::size_t(page.width) * stride * sampleBytes;
    std::vector<std::uint8_t> buffer = takeBuffer(TIFFStripSize(tiff), index, "strip");
    const std::uint16_t sample = page.planarSeparate ? std::uint16_t(channel) : 0;
    const std::size_t offset = page.planarSeparate ? 0 : std::size_t(channel) * sampleBytes;
    for (std::uint32_t row = 0; row < page.height; row += rowsPerStrip) {
        const std::uint32_t strip = TIFFComputeStrip(tiff, row, sample);
        const std::uint32_t rows = std::min(rowsPerStrip, page.height - row);
        const std::size_t expected = rows * rowBytes;
        if (strip >= TIFFNumberOfStrips(tiff))
            fail(pageField(index), "strip " + std::to_string(strip) + " is missing (StripOffsets too short)");
        if (buffer.size() < expected) fail(pageField(index), "strip " + std::to_string(strip) + " has the wrong size");
        const tmsize_t read = TIFFReadEncodedStrip(tiff, strip, buffer.data(), tmsize_t(buffer.size()));
        if (read < tmsize_t(expected))
            fail(pageField(index), "strip " + std::to_string(strip) + " is cut short or damaged" +
                                       (read >= 0 ? ": " + std::to_string(read) + " of " + std::to_string(expected) + " bytes"
                                                  : std::string()));
        for (std::uint32_t r = 0; r < rows; ++r)
            convertRow(page, buffer.data() + r * rowBytes + offset, page.width, stride,
                       out + std::size_t(row + r) * page.width);
    }
}

void TiffFile::readTiles(const TiffPage& page, std::size_t index, int channel, float* out) {
    TIFF* tiff = asTiff(tiff_);
    std::uint32_t tileWidth = 0, tileLength = 0;
    TIFFGetField(tiff, TIFFTAG_TILEWIDTH, &tileWidth);
    TIFFGetField(tiff, TIFFTAG_TILELENGTH, &tileLength);
    if (tileWidth == 0 || tileLength == 0) fail(pageField(index), "TileWidth or TileLength is 0");
    const std::size_t sampleBytes = page.bitsPerSample / 8;
    const std::size_t stride = page.planarSeparate ? 1 : page.samplesPerPixel;
    const std::size_t rowBytes = std::size_t(tileWidth) * stride * sampleBytes;
    const std::size_t expected = rowBytes * tileLength;
    std::vector<std::uint8_t> buffer = takeBuffer(TIFFTileSize(tiff), index, "tile");
    if (buffer.size() < expected) fail(pageField(index), "its tiles have the wrong size");
    const std::uint16_t sample = page.planarSeparate ? std::uint16_t(channel) : 0;
    const std::size_t offset = page.planarSeparate ? 0 : std::size_t(channel) * sampleBytes;
    for (std::uint32_t y = 0; y < page.height; y += tileLength)
        for (std::uint32_t x = 0; x < page.width; x += tileWidth) {
            const std::uint32_t tile = TIFFComputeTile(tiff, x, y, 0, sample);
            if (tile >= TIFFNumberOfTiles(tiff))
                fail(pageField(index), "tile " + std::to_string(tile) + " is missing (TileOffsets too short)");
            const tmsize_t read = TIFFReadEncodedTile(tiff, tile, buffer.data(), tmsize_t(buffer.size()));
            if (read < tmsize_t(expected))
                fail(pageField(index), "tile " + std::to_string(tile) + " is cut short or damaged");
            const std::uint32_t rows = std::min(tileLength, page.height - y);
            const std::uint32_t columns = std::min(tileWidth, page.width - x);
            for (std::uint32_t r = 0; r < rows; ++r)
                convertRow(page, buffer.data() + r * rowBytes + offset, columns, stride,
                           out + std::size_t(y + r) * page.width + x);
        }
}

std::uint64_t TiffFile::contiguousDataOffset(const TiffPage& first) {
    if (first.compression != COMPRESSION_NONE || first.tiled || first.planarSeparate) return 0;
    goToPage(first, 0);
    TIFF* tiff = asTiff(tiff_);
    const std::uint64_t* offsets = nullptr;
    const std::uint64_t* counts = nullptr;
    if (TIFFGetField(tiff, TIFFTAG_STRIPOFFSETS, &offsets) != 1 || TIFFGetField(tiff, TIFFTAG_STRIPBYTECOUNTS, &counts) != 1)
        return 0;
    const std::uint32_t strips = TIFFNumberOfStrips(tiff);
    for (std::uint32_t strip = 0; strip + 1 < strips; ++strip)
        if (offsets[strip + 1] != offsets[strip] + counts[strip]) return 0;
    return strips > 0 ? offsets[0] : 0;
}

void TiffFile::readContiguousPlane(const TiffPage& first, std::uint64_t dataOffset, std::size_t plane, int channel,
                                   float* out) {
    const std::size_t sampleBytes = first.bitsPerSample / 8;
    const std::size_t pixels = std::size_t(first.width) * first.height;
    const std::size_t planeBytes = pixels * first.samplesPerPixel * sampleBytes;
    const std::string field = "image " + std::to_string(plane) + " (after the first page's data)";
    requireMemory(file_, field, double(planeBytes), memoryCap_, "one image");
    std::vector<std::uint8_t> bytes(planeBytes);
    std::ifstream in(file_, std::ios::binary);
    in.seekg(std::streamoff(dataOffset + plane * planeBytes));
    in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(planeBytes));
    if (!in || std::size_t(in.gcount()) != planeBytes)
        throwInputError(file_, field, "is cut short: the file ends before its " + std::to_string(planeBytes) + " bytes");
    if (byteSwapped() && sampleBytes > 1) swapSampleBytes(bytes, sampleBytes);
    convertRow(first, bytes.data() + std::size_t(channel) * sampleBytes, pixels, first.samplesPerPixel, out);
}

}  // namespace tstyles
