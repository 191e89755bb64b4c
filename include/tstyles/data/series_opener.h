// Opening a series from whatever the user has: our manifest (a .json or its folder), NetCDF, NIfTI,
// NRRD, Plot3D, the Hurricane Isabel raw files, TIFF, OME-Zarr, DICOM or VTK (XML and legacy). The format comes
// from the extension, else from a folder's claim or the file's first bytes. docs/readers.md
// describes each reader and the options.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tstyles/data/read_options.h"
#include "tstyles/data/series.h"

namespace tstyles {

// One file (or a dataset folder), or several files that together form a series: the hourly Isabel
// files of one variable, or 3D volumes (NRRD, NIfTI) taken in the given order as time-steps.
Series openSeries(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options);
Series openSeries(const std::filesystem::path& input, const ReadOptions& options);

// As openSeries, but the values stay raw (missing ones NaN): what `tstyles convert` writes. Not
// for manifests, which are already in our form.
Series openRawSeries(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options);

// The name of the format the opener would use ("tstyles manifest", "NetCDF", ...); an InputError
// when it knows none.
std::string seriesFormatName(const std::filesystem::path& input);

// True for inputs that are our manifest form (a .json file, or a folder that no format reads as a
// whole: OME-Zarr stores, DICOM folders and folders of TIFF files are not manifests).
bool isManifestInput(const std::filesystem::path& input);

// The format a file or folder would be read as, judged by its name alone: a format's extension, a
// folder a format claims, a folder holding series.json ("tstyles manifest"); empty for anything
// else (a .json may be a scene). For file browsers: it opens nothing, and rows added to the format
// table show up in it without a change here.
std::string formatNamedBy(const std::filesystem::path& input);

// True for a file whose name ends like a format's files (".nc", ".pvd", ".series", ...).
bool isNamedLikeSeriesFile(const std::filesystem::path& input);

}  // namespace tstyles
