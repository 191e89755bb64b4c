// ImageJ hyperstacks (Fiji, tifffile imagej=True): the "ImageJ=" ImageDescription says how many
// channels, slices and frames the pages are, in ImageJ's order (channel fastest, then slice, frame).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "tiff_layout.h"

namespace tstyles {

struct ImageJDescription {
    std::optional<std::size_t> images;
    std::size_t channels = 1;
    std::size_t slices = 1;
    std::size_t frames = 1;
    std::optional<double> spacing;    // z, in `unit`
    std::optional<double> finterval;  // between frames, in `timeUnit` (seconds when not given)
    std::string unit;
    std::string timeUnit;
};

bool isImageJDescription(const std::string& description);

// The keys we use; the many others ImageJ writes (mode, loop, min, max, ranges, ...) are display
// settings and left alone. A number that is not one, or not positive, is an InputError.
ImageJDescription parseImageJDescription(const std::string& description, const std::filesystem::path& file);

// The planes of the channel asked for, time-step by time-step, with spacing and frame times.
TiffLayout imagejLayout(TiffFile& tiff, std::vector<TiffPage> pages, const ImageJDescription& description,
                        const ReadOptions& options);

// x and y spacing from a page's resolution tags (pixels per unit), 1 where none is given.
glm::dvec2 spacingFromResolution(const TiffPage& page);

}  // namespace tstyles
