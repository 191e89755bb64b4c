// From an ImageJ description and the file's pages to the planes of one channel over time. Files over
// 4 GiB keep one IFD and the images as one run after it (read so when that run is uncompressed).
#include "tiff_imagej.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "../series_assembly.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

constexpr const char* kImageJField = "ImageDescription";

double parsePositive(const std::string& key, const std::string& value, const std::filesystem::path& file) {
    char* end = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(number) || number <= 0.0)
        throwInputError(file, std::string(kImageJField) + " " + key + "=", "\"" + value + "\" is not a positive number");
    return number;
}

std::size_t parseCount(const std::string& key, const std::string& value, const std::filesystem::path& file) {
    const double number = parsePositive(key, value, file);
    if (number != std::floor(number) || number > 1e12)
        throwInputError(file, std::string(kImageJField) + " " + key + "=", "\"" + value + "\" is not a count");
    return std::size_t(number);
}

// Images stored one after another from the first page's data, checked against the file's size.
std::uint64_t contiguousRun(TiffFile& tiff, const TiffPage& first, std::size_t images) {
    const std::uint64_t offset = tiff.contiguousDataOffset(first);
    const std::string field = std::string(kImageJField) + " images=";
    if (offset == 0)
        throwInputError(tiff.path(), field,
                        "says " + std::to_string(images) +
                            " images, the file has 1 page, and its data is not one uncompressed run that could hold the rest");
    const double planeBytes = double(first.width) * first.height * first.samplesPerPixel * (first.bitsPerSample / 8);
    const std::uint64_t size = regularFileSize(tiff.path(), "TIFF file");
    if (double(offset) + planeBytes * double(images) > double(size))
        throwInputError(tiff.path(), field,
                        "says " + std::to_string(images) + " images of " + byteCountText(planeBytes) + " after byte " +
                            std::to_string(offset) + ", the file is cut short at " + std::to_string(size) + " bytes");
    return offset;
}

}  // namespace

bool isImageJDescription(const std::string& description) { return description.rfind("ImageJ=", 0) == 0; }

ImageJDescription parseImageJDescription(const std::string& description, const std::filesystem::path& file) {
    ImageJDescription parsed;
    std::istringstream lines(description);
    std::string line;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::size_t equals = line.find('=');
        if (equals == std::string::npos) continue;
        const std::string key = line.substr(0, equals), value = line.substr(equals + 1);
        if (key == "images") parsed.images = parseCount(key, value, file);
        else if (key == "channels") parsed.channels = parseCount(key, value, file);
        else if (key == "slices") parsed.slices = parseCount(key, value, file);
        else if (key == "frames") parsed.frames = parseCount(key, value, file);
        else if (key == "spacing") parsed.spacing = parsePositive(key, value, file);
        else if (key == "finterval") parsed.finterval = parsePositive(key, value, file);
        else if (key == "unit") parsed.unit = value;
        else if (key == "tunit") parsed.timeUnit = value;
    }
    return parsed;
}

glm::dvec2 spacingFromResolution(const TiffPage& page) {
    return {page.xResolution > 0.0 && std::isfinite(page.xResolution) ? 1.0 / page.xResolution : 1.0,
            page.yResolution > 0.0 && std::isfinite(page.yResolution) ? 1.0 / page.yResolution : 1.0};
}

TiffLayout imagejLayout(TiffFile& tiff, std::vector<TiffPage> pages, const ImageJDescription& description,
                        const ReadOptions& options) {
    const std::filesystem::path& file = tiff.path();
    const double product = double(description.channels) * double(description.slices) * double(description.frames);
    const std::size_t images = description.images.value_or(std::size_t(product));
    if (double(images) != product)
        throwInputError(file, std::string(kImageJField) + " images=",
                        "says " + std::to_string(images) + " images, but channels x slices x frames = " +
                            std::to_string(description.channels) + " x " + std::to_string(description.slices) + " x " +
                            std::to_string(description.frames));
    requireStepCount(file, std::string(kImageJField) + " frames=", description.frames);

    TiffLayout layout;
    layout.format = "ImageJ hyperstack TIFF";
    layout.files = {file};
    if (images != pages.size()) {
        if (pages.size() != 1 || images < pages.size())
            throwInputError(file, std::string(kImageJField) + " images=",
                            "says " + std::to_string(images) + " images, the file has " + std::to_string(pages.size()) +
                                " pages");
        layout.contiguousOffset = contiguousRun(tiff, pages.front(), images);
        layout.notes.push_back("the images after the first are one run of data without IFDs (an ImageJ file over 4 GiB)");
    }
    layout.pages = {std::move(pages)};
    const ChannelChoice channel =
        chooseChannel(options, description.channels, layout.pages[0][0].samplesPerPixel, file, layout.notes);
    layout.sample = channel.sample;
    layout.slices = description.slices;
    layout.steps = description.frames;
    for (std::size_t frame = 0; frame < description.frames; ++frame)
        for (std::size_t slice = 0; slice < description.slices; ++slice)
            layout.planes.push_back({0, (frame * description.slices + slice) * description.channels + channel.planeChannel});
    requireVolumeShape(layout, file, std::string(kImageJField) + " slices=");
    requireSameLayout(layout);

    const glm::dvec2 xy = spacingFromResolution(layout.firstPage());
    layout.spacing = {xy.x, xy.y, description.spacing.value_or(1.0)};
    layout.unit = normalizedLengthUnit(description.unit);
    layout.notes.push_back("ImageJ hyperstack: " + std::to_string(description.channels) + " channel(s) x " +
                           std::to_string(description.slices) + " slices x " + std::to_string(description.frames) +
                           " frames, pages in ImageJ's order (channel fastest, then slice, then frame)");
    if (description.finterval) {
        layout.time.unit = description.timeUnit.empty() ? TimeUnit::Seconds : timeUnitFromText(description.timeUnit);
        for (std::size_t frame = 0; frame < layout.steps; ++frame) layout.times.push_back(double(frame) * *description.finterval);
        std::ostringstream interval;
        interval << *description.finterval;
        layout.notes.push_back("frame times from finterval=" + interval.str() +
                               (description.timeUnit.empty() ? " (seconds)" : " " + description.timeUnit));
    } else {
        for (std::size_t frame = 0; frame < layout.steps; ++frame) layout.times.push_back(double(frame));
        layout.notes.push_back("no finterval=: frames are numbered 0, 1, 2, ...");
    }
    return layout;
}

}  // namespace tstyles
