// One file of a VTK series, whichever encoding it is in: XML (serial or parallel) or legacy. What
// the series needs of it: its point arrays, its grid and placement as a time-step, the values of
// one array. vtk_reader.cpp makes the series of such files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "../source_series.h"
#include "vtk_data_array.h"
#include "vtk_dataset.h"
#include "vtk_legacy_file.h"

namespace tstyles {

struct VtkArraySummary {
    std::string name;
    VtkValueType type;
    std::uint64_t components = 1;
};

// "velocity (3 components)", "temperature": an array as messages and notes name it.
std::string arrayText(const VtkArraySummary& array);

class VtkSeriesFile {
public:
    // Reads the file's description: an XML file's XML (not its appended data; a parallel file's
    // piece files likewise), a legacy file's keywords.
    VtkSeriesFile(const std::filesystem::path& path, std::uint64_t memoryCap);

    const std::filesystem::path& path() const { return path_; }
    // "VTK XML ImageData", "VTK legacy STRUCTURED_POINTS", ...
    const std::string& format() const { return format_; }
    // "ImageData", "STRUCTURED_POINTS", ...: what a note calls the file's kind.
    const std::string& kindName() const { return kindName_; }
    const std::vector<VtkArraySummary>& pointArrays() const { return pointArrays_; }
    const std::string& activeScalars() const { return activeScalars_; }
    const std::vector<std::string>& cellArrays() const { return cellArrays_; }

    // The point array `name`, or an InputError naming the file and `--var` that lists those there
    // are (and says so when `name` is a cell array).
    const VtkArraySummary& pointArray(const std::string& name) const;
    // How the array's values are stored ("appended (raw), compressed by ...", "BINARY (big-endian)").
    std::string encoding(const std::string& name) const;
    // How the file holds its extent (pieces, piece files), for `info`; may be empty.
    std::vector<std::string> layoutNotes() const;

    // The time-step's grid and placement; mirrorX is set where the frame is a reflection that
    // the values must be reversed along x to undo (oriented_axes.h).
    void placeStep(SourceStep& step, bool& mirrorX) const;

private:
    std::filesystem::path path_;
    std::uint64_t memoryCap_ = 0;
    std::string format_;
    std::string kindName_;
    std::vector<VtkArraySummary> pointArrays_;
    std::string activeScalars_;
    std::vector<std::string> cellArrays_;
    std::shared_ptr<const VtkXmlFile> xml_;  // header only
    std::optional<VtkDataset> dataset_;
    std::optional<VtkLegacyFile> legacy_;
};

// The values of the point array `name` of the file at `path`, x fastest, one per point.
std::vector<float> readVtkSeriesValues(const std::filesystem::path& path, const std::string& name,
                                       std::uint64_t memoryCap);

}  // namespace tstyles
