// Extents, pieces and frames of VTK ImageData, RectilinearGrid and StructuredGrid files (serial or
// parallel), and the assembly of a whole-extent array from the pieces that hold it (the parallel
// writers split a volume this way, within one file or in a file per piece).
#include "vtk_dataset.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/interval.h"

namespace tstyles {
namespace {

std::vector<double> numbersIn(const VtkXmlFile& file, const pugi::xml_node& node, const char* attribute,
                              std::size_t count) {
    const std::string text = node.attribute(attribute).as_string();
    const std::string field = std::string(node.name()) + " " + attribute;
    std::vector<double> numbers;
    const char* position = text.data();
    const char* end = text.data() + text.size();
    while (position < end) {
        if (std::isspace(static_cast<unsigned char>(*position))) {
            ++position;
            continue;
        }
        double value = 0.0;
        const auto [next, error] = std::from_chars(position, end, value);
        if (error != std::errc() || !std::isfinite(value) || numbers.size() == count)
            throwInputError(file.path, field, "'" + text + "' is not " + std::to_string(count) + " finite numbers");
        numbers.push_back(value);
        position = next;
    }
    if (numbers.size() != count)
        throwInputError(file.path, field, "'" + text + "' is not " + std::to_string(count) + " finite numbers");
    return numbers;
}

VtkExtent extentIn(const VtkXmlFile& file, const pugi::xml_node& node, const char* attribute) {
    const std::vector<double> numbers = numbersIn(file, node, attribute, 6);
    VtkExtent extent;
    for (std::size_t index = 0; index < 6; ++index) {
        const double value = numbers[index];
        if (value != std::floor(value) || std::abs(value) > double(std::numeric_limits<std::int32_t>::max()))
            throwInputError(file.path, std::string(node.name()) + " " + attribute,
                            "extent bounds must be whole numbers of at most 2^31 - 1 in size");
        extent.bounds[index] = std::int64_t(value);
    }
    for (std::size_t axis = 0; axis < 3; ++axis)
        if (extent.bounds[2 * axis] > extent.bounds[2 * axis + 1])
            throwInputError(file.path, std::string(node.name()) + " " + attribute,
                            std::string("the extent along ") + "xyz"[axis] + " ends before it starts");
    return extent;
}

bool contains(const VtkExtent& outer, const VtkExtent& inner) {
    for (std::size_t axis = 0; axis < 3; ++axis)
        if (inner.bounds[2 * axis] < outer.bounds[2 * axis] || inner.bounds[2 * axis + 1] > outer.bounds[2 * axis + 1])
            return false;
    return true;
}

void describeFrame(const VtkXmlFile& file, VtkDataset& dataset) {
    const pugi::xml_node node = file.dataset;
    if (node.attribute("Origin")) {
        const auto origin = numbersIn(file, node, "Origin", 3);
        dataset.origin = {origin[0], origin[1], origin[2]};
    }
    if (node.attribute("Spacing")) {
        const auto spacing = numbersIn(file, node, "Spacing", 3);
        dataset.spacing = {spacing[0], spacing[1], spacing[2]};
    }
    if (node.attribute("Direction")) {
        const auto direction = numbersIn(file, node, "Direction", 9);
        std::copy(direction.begin(), direction.end(), dataset.direction.begin());
    }
}

VtkPiece describePiece(const VtkXmlFile& file, const VtkDataset& dataset, const pugi::xml_node& node) {
    VtkPiece piece;
    piece.node = node;
    piece.extent = extentIn(file, node, "Extent");
    if (!contains(dataset.whole, piece.extent))
        throwInputError(file.path, "Piece Extent", "the piece reaches outside the WholeExtent");
    piece.pointArrays = describeArrays(file, node.child("PointData"));
    return piece;
}

std::string arrayList(const std::vector<VtkDataArray>& arrays) {
    std::string list;
    for (const VtkDataArray& array : arrays)
        list += (list.empty() ? "" : ", ") + array.name +
                (array.components > 1 ? " (" + std::to_string(array.components) + " components)" : "");
    return list;
}

// Fills the whole extent from the pieces, `width` floats per point, each piece's values read by
// `readPiece`; a point no piece holds is an error (the values would be made up).
std::vector<float> assemble(const VtkXmlFile& file, const VtkDataset& dataset, std::size_t width,
                            std::uint64_t memoryCap, const std::function<std::vector<float>(const VtkPiece&)>& readPiece) {
    if (dataset.pieces.size() == 1 && dataset.pieces.front().extent.bounds == dataset.whole.bounds)
        return readPiece(dataset.pieces.front());
    const std::uint64_t points = dataset.whole.pointCount();
    requireMemory(file.path, "WholeExtent", double(points) * double(width * 4 + 1), memoryCap,
                  "the values of one time-step");
    std::vector<float> whole(points * width, 0.0f);
    std::vector<bool> covered(points, false);
    const glm::ivec3 dims = dataset.whole.dims();
    for (const VtkPiece& piece : dataset.pieces) {
        const std::vector<float> values = readPiece(piece);
        const glm::ivec3 size = piece.extent.dims();
        std::size_t source = 0;
        for (int z = 0; z < size.z; ++z)
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x, ++source) {
                    const std::size_t target =
                        std::size_t(piece.extent.bounds[0] - dataset.whole.bounds[0] + x) +
                        std::size_t(dims.x) * (std::size_t(piece.extent.bounds[2] - dataset.whole.bounds[2] + y) +
                                               std::size_t(dims.y) * std::size_t(piece.extent.bounds[4] -
                                                                                 dataset.whole.bounds[4] + z));
                    std::copy_n(values.begin() + std::ptrdiff_t(source * width), width,
                                whole.begin() + std::ptrdiff_t(target * width));
                    covered[target] = true;
                }
    }
    for (std::size_t point = 0; point < points; ++point)
        if (!covered[point])
            throwInputError(file.path, "Piece",
                            "the pieces do not cover the WholeExtent: point " + std::to_string(point) +
                                " (x fastest) is in none of them");
    return whole;
}

}  // namespace

const char* toString(VtkGridKind kind) {
    switch (kind) {
        case VtkGridKind::Image: return "ImageData";
        case VtkGridKind::Rectilinear: return "RectilinearGrid";
        case VtkGridKind::Structured: return "StructuredGrid";
    }
    return "ImageData";
}

glm::ivec3 VtkExtent::dims() const {
    return {int(bounds[1] - bounds[0] + 1), int(bounds[3] - bounds[2] + 1), int(bounds[5] - bounds[4] + 1)};
}

std::uint64_t VtkExtent::pointCount() const {
    const glm::ivec3 size = dims();
    return std::uint64_t(size.x) * std::uint64_t(size.y) * std::uint64_t(size.z);
}

namespace {

VtkGridKind gridKindOf(const VtkXmlFile& file) {
    std::string element = file.dataset.name();
    if (file.parallel) element.erase(0, 1);  // PImageData, PRectilinearGrid, PStructuredGrid
    return element == "StructuredGrid"    ? VtkGridKind::Structured
           : element == "RectilinearGrid" ? VtkGridKind::Rectilinear
                                          : VtkGridKind::Image;
}

VtkExtent wholeExtentOf(const VtkXmlFile& file, bool volume) {
    const VtkExtent whole = extentIn(file, file.dataset, "WholeExtent");
    // Each axis fits an int and the point count a double exactly; the memory cap decides the rest.
    double points = 1.0;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        const std::int64_t size = whole.bounds[2 * axis + 1] - whole.bounds[2 * axis] + 1;
        if (size > std::int64_t(std::numeric_limits<std::int32_t>::max()))
            throwInputError(file.path, "WholeExtent", std::string("the extent along ") + "xyz"[axis] + " is too large");
        points *= double(size);
    }
    if (points > 9.0e15) throwInputError(file.path, "WholeExtent", "the extent holds too many points to be read");
    const glm::ivec3 dims = whole.dims();
    if (volume && (dims.x < 2 || dims.y < 2 || dims.z < 2))
        throwInputError(file.path, "WholeExtent",
                        "a volume needs at least 2 samples along x, y and z, found " + std::to_string(dims.x) + " x " +
                            std::to_string(dims.y) + " x " + std::to_string(dims.z));
    return whole;
}

bool sameNumber(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)}); }

// A piece file of a .pvti must place its points as the .pvti does.
void requireSameFrame(const VtkXmlFile& parallel, const VtkDataset& dataset, const VtkXmlFile& pieceFile,
                      const VtkDataset& piece) {
    const auto differs = [&](const char* field) {
        throwInputError(pieceFile.path, field,
                        std::string("differs from the ") + field + " of " + parallel.path.filename().string() +
                            ": the pieces of one image share its frame");
    };
    for (int axis = 0; axis < 3; ++axis) {
        if (!sameNumber(dataset.origin[axis], piece.origin[axis])) differs("Origin");
        if (!sameNumber(dataset.spacing[axis], piece.spacing[axis])) differs("Spacing");
    }
    for (std::size_t index = 0; index < 9; ++index)
        if (!sameNumber(dataset.direction[index], piece.direction[index])) differs("Direction");
}

VtkDataset describeDataset(const VtkXmlFile& file, std::uint64_t memoryCap, bool volume);

// A parallel file's <Piece Extent Source>: each Source a serial file of the same kind beside it,
// whose own pieces join the dataset's.
void describePieceFiles(const VtkXmlFile& file, VtkDataset& dataset, std::uint64_t memoryCap) {
    for (const pugi::xml_node& node : file.dataset.children("Piece")) {
        const std::string where = "Piece (line " + std::to_string(lineOf(file, node)) + ")";
        const std::string source = node.attribute("Source").as_string();
        if (source.empty())
            throwInputError(file.path, where, "has no Source: a parallel file's pieces are files of their own");
        const std::filesystem::path path = file.path.parent_path() / source;
        std::error_code error;
        if (!std::filesystem::is_regular_file(path, error))
            throwInputError(file.path, where, "Source '" + source + "': the file '" + path.string() + "' does not exist");
        std::shared_ptr<const VtkXmlFile> pieceFile = loadVtkXmlFile(path, file.headerOnly, memoryCap);
        if (pieceFile->parallel || gridKindOf(*pieceFile) != dataset.kind)
            throwInputError(path, "type",
                            std::string("a piece of ") + file.path.filename().string() + " must be " +
                                toString(dataset.kind) + " data, not " + pieceFile->dataset.name());
        const VtkDataset pieceDataset = describeDataset(*pieceFile, memoryCap, false);
        if (dataset.kind == VtkGridKind::Image) requireSameFrame(file, dataset, *pieceFile, pieceDataset);
        for (VtkPiece piece : pieceDataset.pieces) {
            if (!contains(dataset.whole, piece.extent))
                throwInputError(path, "Piece Extent",
                                "the piece reaches outside the WholeExtent of " + file.path.filename().string());
            piece.source = pieceFile;
            dataset.pieces.push_back(std::move(piece));
        }
        ++dataset.pieceFiles;
    }
}

VtkDataset describeDataset(const VtkXmlFile& file, std::uint64_t memoryCap, bool volume) {
    VtkDataset dataset;
    dataset.kind = gridKindOf(file);
    dataset.whole = wholeExtentOf(file, volume);
    if (dataset.kind == VtkGridKind::Image) describeFrame(file, dataset);
    const char* pointData = file.parallel ? "PPointData" : "PointData";
    const char* cellData = file.parallel ? "PCellData" : "CellData";
    const char* arrayElement = file.parallel ? "PDataArray" : "DataArray";
    pugi::xml_node described = file.dataset;  // where the PointData and CellData elements are
    if (file.parallel) {
        describePieceFiles(file, dataset, memoryCap);
    } else {
        for (const pugi::xml_node& node : file.dataset.children("Piece"))
            dataset.pieces.push_back(describePiece(file, dataset, node));
        if (!dataset.pieces.empty()) described = dataset.pieces.front().node;
    }
    if (dataset.pieces.empty()) throwInputError(file.path, "Piece", "the file has no <Piece>: there is no data");
    dataset.activeScalars = described.child(pointData).attribute("Scalars").as_string();
    for (const pugi::xml_node& array : described.child(cellData).children(arrayElement))
        dataset.cellArrays.push_back(array.attribute("Name").as_string());
    return dataset;
}

}  // namespace

const VtkXmlFile& fileOf(const VtkXmlFile& described, const VtkPiece& piece) {
    return piece.source ? *piece.source : described;
}

VtkDataset describeVtkDataset(const VtkXmlFile& file, std::uint64_t memoryCap) {
    return describeDataset(file, memoryCap, true);
}

const VtkDataArray& pointArrayNamed(const VtkXmlFile& file, const VtkDataset& dataset, const std::string& name) {
    const auto& arrays = dataset.pieces.front().pointArrays;
    for (const VtkDataArray& array : arrays)
        if (array.name == name) return array;
    throwInputError(file.path, "--var", missingPointArrayProblem(name, arrayList(arrays), dataset.cellArrays));
}

std::vector<float> readVtkPointArray(const VtkXmlFile& file, const VtkDataset& dataset, const std::string& name,
                                     std::uint64_t memoryCap) {
    return assemble(file, dataset, 1, memoryCap, [&](const VtkPiece& piece) {
        for (const VtkDataArray& array : piece.pointArrays)
            if (array.name == name)
                return readPointValues(fileOf(file, piece), array, piece.extent.pointCount(), memoryCap);
        throwInputError(fileOf(file, piece).path, "Piece (line " + std::to_string(lineOf(fileOf(file, piece), piece.node)) + ")",
                        "has no point array '" + name + "' though the first piece has");
    });
}

std::array<std::vector<double>, 3> readVtkCoordinates(const VtkXmlFile& file, const VtkDataset& dataset,
                                                      std::uint64_t memoryCap) {
    const glm::ivec3 dims = dataset.whole.dims();
    std::array<std::vector<double>, 3> coordinates;
    std::array<std::vector<bool>, 3> covered;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        coordinates[axis].assign(std::size_t(dims[int(axis)]), 0.0);
        covered[axis].assign(std::size_t(dims[int(axis)]), false);
    }
    for (const VtkPiece& piece : dataset.pieces) {
        const VtkXmlFile& holder = fileOf(file, piece);
        const std::string where = "Coordinates (line " + std::to_string(lineOf(holder, piece.node)) + ")";
        const std::vector<VtkDataArray> arrays = describeArrays(holder, piece.node.child("Coordinates"));
        if (arrays.size() != 3 || arrays[0].components != 1 || arrays[1].components != 1 || arrays[2].components != 1)
            throwInputError(holder.path, where, "a rectilinear grid's piece needs three one-component DataArrays: x, y, z");
        const glm::ivec3 size = piece.extent.dims();
        for (std::size_t axis = 0; axis < 3; ++axis) {
            const std::vector<float> values =
                readPointValues(holder, arrays[axis], std::uint64_t(size[int(axis)]), memoryCap);
            const std::size_t start = std::size_t(piece.extent.bounds[2 * axis] - dataset.whole.bounds[2 * axis]);
            for (std::size_t index = 0; index < values.size(); ++index) {
                const double value = values[index];
                if (!std::isfinite(value))
                    throwInputError(holder.path, where, std::string(1, "xyz"[axis]) + " coordinate " +
                                                          std::to_string(index) + " is not finite");
                double& kept = coordinates[axis][start + index];
                if (covered[axis][start + index] && kept != value)
                    throwInputError(holder.path, where,
                                    std::string("the pieces disagree on ") + "xyz"[axis] + " coordinate " +
                                        std::to_string(start + index) + " of the WholeExtent");
                kept = value;
                covered[axis][start + index] = true;
            }
        }
    }
    for (std::size_t axis = 0; axis < 3; ++axis)
        for (std::size_t index = 0; index < coordinates[axis].size(); ++index) {
            if (!covered[axis][index])
                throwInputError(file.path, "Piece",
                                std::string("the pieces do not cover the WholeExtent: no piece gives ") + "xyz"[axis] +
                                    " coordinate " + std::to_string(index));
            if (index > 0 && !(coordinates[axis][index] > coordinates[axis][index - 1]))
                throwInputError(file.path, "Coordinates",
                                std::string("the ") + "xyz"[axis] + " coordinates must increase strictly: " +
                                    formatNumber(coordinates[axis][index]) + " follows " +
                                    formatNumber(coordinates[axis][index - 1]));
        }
    return coordinates;
}

std::vector<glm::vec3> readVtkPoints(const VtkXmlFile& file, const VtkDataset& dataset, std::uint64_t memoryCap) {
    const std::vector<float> coordinates = assemble(file, dataset, 3, memoryCap, [&](const VtkPiece& piece) {
        const VtkXmlFile& holder = fileOf(file, piece);
        const std::vector<VtkDataArray> arrays = describeArrays(holder, piece.node.child("Points"));
        if (arrays.size() != 1 || arrays.front().components != 3)
            throwInputError(holder.path, "Points (line " + std::to_string(lineOf(holder, piece.node)) + ")",
                            "a structured grid's piece needs one <Points> DataArray of 3 components");
        return readPointComponents(holder, arrays.front(), piece.extent.pointCount(), memoryCap);
    });
    std::vector<glm::vec3> points(coordinates.size() / 3);
    for (std::size_t point = 0; point < points.size(); ++point)
        points[point] = {coordinates[3 * point], coordinates[3 * point + 1], coordinates[3 * point + 2]};
    return points;
}

}  // namespace tstyles
