// The readers the opener knows, in one table: adding a format is adding one row (format_table.cpp).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "source_series.h"
#include "tstyles/data/format_listing.h"
#include "tstyles/data/read_options.h"

namespace tstyles {

struct SeriesFormat {
    std::string name;
    std::vector<std::string> extensions;                        // lower case, with the dot: ".nii.gz"
    std::vector<FormatMimeType> mimeTypes;                      // of its files, for the desktop
    std::string spelling;                                       // how its files look, for messages
    std::vector<std::string> options;                           // the format-only options it takes: "--var", ...
    std::function<bool(const std::filesystem::path&)> sniff;    // recognises the content; may be empty
    // Opens one file, or several that form one series.
    std::function<SourceSeries(const std::vector<std::filesystem::path>&, const ReadOptions&)> open;
    // Recognises a folder the format reads as one series (an OME-Zarr store, a DICOM folder, a folder
    // of TIFF files); empty for formats read from files only. A folder no format claims is a manifest's.
    std::function<bool(const std::filesystem::path&)> claimsFolder;
};

inline constexpr const char* kPlot3DFormatName = "Plot3D";

const std::vector<SeriesFormat>& seriesFormats();

}  // namespace tstyles
