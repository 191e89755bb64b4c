// Where the planes of a TIFF volume series are (file, page), with spacing and times: what the ImageJ,
// OME and plain-page readings each work out, and what tiff_reader.cpp turns into a SourceSeries.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tiff_file.h"
#include "tstyles/data/read_options.h"
#include "tstyles/data/time_axis.h"

namespace tstyles {

struct TiffPlaneRef {
    std::size_t file = 0;
    std::size_t page = 0;  // the IFD's index; with a contiguous run, the image's index in the run
};

struct TiffLayout {
    std::string format;  // "ImageJ hyperstack TIFF", "OME-TIFF", "TIFF" for `info`
    std::vector<std::filesystem::path> files;
    std::vector<std::vector<TiffPage>> pages;  // per file, every IFD
    std::vector<TiffPlaneRef> planes;          // slice z of time-step t at t * slices + z
    std::size_t slices = 0;
    std::size_t steps = 0;
    int sample = 0;  // which sample of a pixel (SamplesPerPixel > 1)
    // ImageJ over 4 GiB: not 0, the byte where file 0's run of images starts.
    std::uint64_t contiguousOffset = 0;
    glm::dvec3 spacing{1.0};
    std::string unit;  // of the spacing: "um", "nm", ...; empty: unknown
    TimeAxis time;
    std::vector<double> times;  // per time-step
    std::vector<std::string> notes;

    // The page that describes every plane's size and type.
    const TiffPage& firstPage() const {
        return contiguousOffset != 0 ? pages[0][0] : pages[planes.front().file][planes.front().page];
    }
};

// The channel the user asked for (--channel, default 0) among `planeChannels` channels stored as
// planes times `samples` samples per pixel: the plane channel and the sample. Out of range is an
// InputError; with several channels a note says which one was taken.
struct ChannelChoice {
    std::size_t planeChannel = 0;
    int sample = 0;
};
ChannelChoice chooseChannel(const ReadOptions& options, std::size_t planeChannels, std::size_t samples,
                            const std::filesystem::path& file, std::vector<std::string>& notes);

// "um" for every spelling of micrometre (micron, µm, \u00B5m), the other lengths as they are; ""
// for pixel or none.
std::string normalizedLengthUnit(const std::string& unit);
// Micrometres in one `unit` (normalized), or nothing for an unknown unit.
std::optional<double> micrometresPer(const std::string& unit);
// "s", "sec", "ms", "min", "h", ...: the TimeUnit, or None when unknown.
TimeUnit timeUnitFromText(const std::string& unit);

// Every page of a volume must have the first page's size and sample type: a page that differs is
// an InputError naming it.
void requireSameLayout(const TiffLayout& layout);

// A volume needs at least 2 samples along x, y and z.
void requireVolumeShape(const TiffLayout& layout, const std::filesystem::path& file, const std::string& field);

}  // namespace tstyles
