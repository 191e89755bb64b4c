// A VTK file as a time-step: XML files through vtk_dataset.cpp, legacy ones through
// vtk_legacy_file.cpp; both become the same grids (rectilinear, uneven where the coordinates are,
// or structured) and placements.
#include "vtk_series_file.h"

#include <algorithm>

#include "../oriented_axes.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/axis_nodes.h"

namespace tstyles {
namespace {

// The ImageData frame: VTK places point (i, j, k) at Origin + Direction * ((i, j, k) * Spacing),
// counting i, j, k from 0 even when the extent starts elsewhere.
OrientedAxes imageFrame(const VtkXmlFile& file, const VtkDataset& dataset) {
    const auto& d = dataset.direction;
    std::array<glm::dvec3, 3> axes{};
    for (int column = 0; column < 3; ++column)
        axes[std::size_t(column)] = glm::dvec3(d[std::size_t(column)], d[std::size_t(3 + column)],
                                               d[std::size_t(6 + column)]) *
                                    dataset.spacing[column];
    const glm::dvec3 first = dataset.origin + axes[0] * double(dataset.whole.bounds[0]) +
                             axes[1] * double(dataset.whole.bounds[2]) + axes[2] * double(dataset.whole.bounds[4]);
    return orientAxes(first, axes, dataset.whole.dims(), file.path, "Spacing and Direction");
}

// A rectilinear grid's coordinates as a grid with uneven axes where they are uneven: the first
// node at the placement's origin, the axes along x, y and z.
void placeRectilinear(const std::array<std::vector<double>, 3>& coordinates, const glm::ivec3& dims, SourceStep& step) {
    RectilinearGrid grid;
    grid.dims = dims;
    Placement placement;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        // Even within what float32 coordinates can say: 1e-5 of the extent, (count - 1) mean gaps.
        AxisNodes nodes = axisNodesOf(coordinates[axis], 1e-5 * double(coordinates[axis].size() - 1));
        placement.origin[int(axis)] = nodes.origin;
        grid.spacing[int(axis)] = nodes.spacing;
        grid.axisPositions[axis] = std::move(nodes.positions);
    }
    step.grid = grid;
    step.placement = placement;
}

void placeStructured(const glm::ivec3& dims, std::vector<glm::vec3> points, const std::filesystem::path& path,
                     const char* field, SourceStep& step) {
    StructuredGrid grid = makeStructuredGrid(dims, std::move(points), path);
    if (const auto problem = findGridProblem(grid)) throwInputError(path, field, *problem);
    step.grid = std::move(grid);
}

void placeEvenGrid(const OrientedAxes& frame, const glm::ivec3& dims, SourceStep& step) {
    RectilinearGrid grid;
    grid.dims = dims;
    grid.spacing = frame.spacing;
    step.grid = grid;
    step.placement = frame.placement;
}

}  // namespace

std::string arrayText(const VtkArraySummary& array) {
    return array.name + (array.components > 1 ? " (" + std::to_string(array.components) + " components)" : "");
}

VtkSeriesFile::VtkSeriesFile(const std::filesystem::path& path, std::uint64_t memoryCap)
    : path_(path), memoryCap_(memoryCap) {
    if (looksLikeVtkLegacy(path)) {
        legacy_ = describeVtkLegacyFile(path, memoryCap);
        kindName_ = legacyDatasetName(legacy_->kind);
        format_ = "VTK legacy " + kindName_;
        for (const VtkLegacyArray& array : legacy_->pointArrays)
            pointArrays_.push_back({array.name, array.type, array.components});
        activeScalars_ = legacy_->activeScalars;
        cellArrays_ = legacy_->cellArrays;
        return;
    }
    xml_ = loadVtkXmlFile(path, true, memoryCap);
    dataset_ = describeVtkDataset(*xml_, memoryCap);
    kindName_ = toString(dataset_->kind);
    format_ = "VTK XML " + kindName_;
    for (const VtkDataArray& array : dataset_->pieces.front().pointArrays)
        pointArrays_.push_back({array.name, array.type, array.components});
    activeScalars_ = dataset_->activeScalars;
    cellArrays_ = dataset_->cellArrays;
}

const VtkArraySummary& VtkSeriesFile::pointArray(const std::string& name) const {
    for (const VtkArraySummary& array : pointArrays_)
        if (array.name == name) return array;
    std::string list;
    for (const VtkArraySummary& array : pointArrays_) list += (list.empty() ? "" : ", ") + arrayText(array);
    throwInputError(path_, "--var", missingPointArrayProblem(name, list, cellArrays_));
}

std::string VtkSeriesFile::encoding(const std::string& name) const {
    if (legacy_) return legacy_->binary ? "BINARY (big-endian)" : "ASCII";
    const VtkDataArray& array = pointArrayNamed(*xml_, *dataset_, name);
    const VtkXmlFile& file = fileOf(*xml_, dataset_->pieces.front());
    std::string text = array.format;
    if (array.format == "appended")
        text += file.appendedEncoding == VtkByteStream::Encoding::Raw ? " (raw)" : " (base64)";
    if (array.format != "ascii") {
        if (file.layout.compressor != VtkCompressor::None) text += ", compressed by " + toString(file.layout.compressor);
        text += file.layout.headerBytes == 8 ? ", UInt64 headers" : ", UInt32 headers";
        text += file.layout.bigEndian ? ", big-endian" : ", little-endian";
    }
    return text;
}

std::vector<std::string> VtkSeriesFile::layoutNotes() const {
    if (!dataset_) return {};
    const std::string name = path_.filename().string();
    const std::string pieces = std::to_string(dataset_->pieces.size()) + " pieces";
    if (dataset_->pieceFiles > 0)
        return {name + " is parallel: " + pieces + " in " + std::to_string(dataset_->pieceFiles) +
                " files, assembled into its WholeExtent"};
    if (dataset_->pieces.size() > 1) return {name + " holds " + pieces + ", assembled into its WholeExtent"};
    return {};
}

void VtkSeriesFile::placeStep(SourceStep& step, bool& mirrorX) const {
    mirrorX = false;
    if (legacy_) {
        if (legacy_->kind == VtkGridKind::Rectilinear)
            return placeRectilinear(readVtkLegacyCoordinates(*legacy_, memoryCap_), legacy_->dims, step);
        if (legacy_->kind == VtkGridKind::Structured)
            return placeStructured(legacy_->dims, readVtkLegacyPoints(*legacy_, memoryCap_), path_, "POINTS", step);
        const std::array<glm::dvec3, 3> axes{glm::dvec3(legacy_->spacing.x, 0.0, 0.0),
                                             glm::dvec3(0.0, legacy_->spacing.y, 0.0),
                                             glm::dvec3(0.0, 0.0, legacy_->spacing.z)};
        const OrientedAxes frame = orientAxes(legacy_->origin, axes, legacy_->dims, path_, "SPACING");
        mirrorX = frame.mirrorX;
        return placeEvenGrid(frame, legacy_->dims, step);
    }
    if (dataset_->kind == VtkGridKind::Image) {
        const OrientedAxes frame = imageFrame(*xml_, *dataset_);
        mirrorX = frame.mirrorX;
        return placeEvenGrid(frame, dataset_->whole.dims(), step);
    }
    // Coordinates and points are in the data, past the header.
    const auto file = loadVtkXmlFile(path_, false, memoryCap_);
    const VtkDataset dataset = describeVtkDataset(*file, memoryCap_);
    if (dataset.kind == VtkGridKind::Rectilinear)
        return placeRectilinear(readVtkCoordinates(*file, dataset, memoryCap_), dataset.whole.dims(), step);
    placeStructured(dataset.whole.dims(), readVtkPoints(*file, dataset, memoryCap_), path_, "Points", step);
}

std::vector<float> readVtkSeriesValues(const std::filesystem::path& path, const std::string& name,
                                       std::uint64_t memoryCap) {
    if (looksLikeVtkLegacy(path)) return readVtkLegacyPointArray(describeVtkLegacyFile(path, memoryCap), name, memoryCap);
    const auto file = loadVtkXmlFile(path, false, memoryCap);
    return readVtkPointArray(*file, describeVtkDataset(*file, memoryCap), name, memoryCap);
}

}  // namespace tstyles
