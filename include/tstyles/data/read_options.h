// What a user may ask of a reader beyond "open this file": the variable, which time-steps, the value
// range, a memory limit and what to do when it is exceeded, a target resolution. Shared by every
// reader and by the manifest loader's front ends (`info`, `render`, `view`, `convert`).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/reading_monitor.h"
#include "tstyles/data/series.h"

namespace tstyles {

// Time-steps first, first + stride, ... below end (Python's first:end:stride); no end: to the last.
struct StepSelection {
    std::size_t first = 0;
    std::optional<std::size_t> end;
    std::size_t stride = 1;
};

// What a series larger than the allowed memory becomes: refused (the default), read at a lower
// resolution, or read with fewer time-steps.
enum class MemoryFit { Refuse, Resolution, Steps };

struct ReadOptions {
    std::string variable;                          // NetCDF, Plot3D: the variable (--var)
    std::string timeDimension;                     // NetCDF: the time dimension when it is not found (--time-dim)
    bool indexAxes = false;                        // NetCDF: unit spacing instead of coordinate variables
    std::optional<StepSelection> steps;            // --steps first:end:stride
    std::optional<std::array<double, 2>> valueRange;  // --range lo:hi; default: from the data
    std::optional<glm::ivec3> resampleTo;          // --resample NXxNYxNZ
    std::optional<glm::ivec3> rawDims;             // Isabel raw files: dims (default 500x500x100); plain TIFF: one volume
    std::optional<int> channel;                    // TIFF, OME-Zarr: which channel of a multi-channel image (--channel)
    std::string seriesChoice;                      // DICOM: the series, by instance UID or number in `info` (--series)
    std::string pageAxes;                          // plain TIFF: what the pages are, slowest first, e.g. TZYX (--axes)
    std::optional<int> level;                      // OME-Zarr, OME-TIFF: the resolution level, 0 the finest (--level)
    std::optional<std::uint64_t> maxMemoryBytes;   // --max-memory
    MemoryFit fit = MemoryFit::Refuse;             // --fit
    DensityPrecision precision = DensityPrecision::Bits16;  // --precision
    // Plot3D: the solution (or function) files, one per time-step; given, the input is a grid file.
    std::vector<std::filesystem::path> solutionFiles;   // --solution
    int block = 0;                                      // --block
    double gamma = 1.4;                                 // --gamma
    // Who hears the readers' stages and progress (the isolated reading's child); not owned, null
    // when nobody listens. Not an option of the user's.
    ReadingMonitor* monitor = nullptr;
};

// Parsers for the command-line spellings; a bad spelling is an InputError naming `option`.
StepSelection parseStepSelection(const std::string& text, const std::string& option);
std::array<double, 2> parseValueRange(const std::string& text, const std::string& option);
glm::ivec3 parseDims(const std::string& text, const std::string& option);
// "512M", "2G", "1.5GiB", "800000" (bytes); K, M, G, T are powers of 1024.
std::uint64_t parseMemorySize(const std::string& text, const std::string& option);
DensityPrecision parseDensityPrecision(const std::string& text, const std::string& option);
MemoryFit parseMemoryFit(const std::string& text, const std::string& option);

std::size_t bytesPerDensity(DensityPrecision precision);
int precisionBits(DensityPrecision precision);

// The indices of `count` time-steps that the selection keeps, in order.
std::vector<std::size_t> selectedSteps(const std::optional<StepSelection>& selection, std::size_t count);

}  // namespace tstyles
