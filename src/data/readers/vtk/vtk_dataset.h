// One .vti (ImageData), .vtr (RectilinearGrid) or .vts (StructuredGrid) file as a volume, or a
// parallel .pvti, .pvtr or .pvts whose pieces are files of their own: its extent and pieces, its
// frame (origin, spacing, direction) and its point arrays; the values of one array, the rectilinear
// grid's coordinates or the structured grid's points, assembled from the pieces that cover the
// extent.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "vtk_data_array.h"
#include "vtk_xml_file.h"

namespace tstyles {

struct VtkExtent {
    std::array<std::int64_t, 6> bounds{};  // x0 x1 y0 y1 z0 z1, inclusive
    glm::ivec3 dims() const;
    std::uint64_t pointCount() const;
};

struct VtkPiece {
    pugi::xml_node node;
    VtkExtent extent;
    std::vector<VtkDataArray> pointArrays;
    // The file that holds the piece, for a parallel file's <Piece Source>; null: the file described.
    std::shared_ptr<const VtkXmlFile> source;
};

// The file whose node and arrays `piece` refers to.
const VtkXmlFile& fileOf(const VtkXmlFile& described, const VtkPiece& piece);

enum class VtkGridKind { Image, Rectilinear, Structured };

// "ImageData", "RectilinearGrid", "StructuredGrid": the element VTK names it by.
const char* toString(VtkGridKind kind);

struct VtkDataset {
    VtkGridKind kind = VtkGridKind::Image;
    VtkExtent whole;
    glm::dvec3 origin{0.0};
    glm::dvec3 spacing{1.0};
    std::array<double, 9> direction{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row by row, as VTK writes it
    std::string activeScalars;  // <PointData Scalars="...">, may be empty
    std::vector<VtkPiece> pieces;
    std::vector<std::string> cellArrays;  // named only: they are not read
    std::size_t pieceFiles = 0;           // of a parallel file: how many files hold its pieces
};

// Checks the extents (a volume of at least 2 points along each axis; pieces inside the whole
// extent) and the frame's numbers; arrays are described, not read. A parallel file's piece files
// are loaded (as far as `file` was: header only or whole) and must be serial files of the same kind
// with the same frame; `memoryCap` bounds what they take.
VtkDataset describeVtkDataset(const VtkXmlFile& file, std::uint64_t memoryCap);

// The first piece's point array named `name` (the same name in every piece), or an InputError that
// lists the arrays there are.
const VtkDataArray& pointArrayNamed(const VtkXmlFile& file, const VtkDataset& dataset, const std::string& name);

// The values of a point array over the whole extent, x fastest (one per point: vectors as
// magnitudes). The pieces must cover the extent.
std::vector<float> readVtkPointArray(const VtkXmlFile& file, const VtkDataset& dataset, const std::string& name,
                                     std::uint64_t memoryCap);

// A rectilinear grid's x, y and z coordinates over the whole extent, from its pieces' <Coordinates>
// (pieces that share a line must agree on it); each must increase strictly.
std::array<std::vector<double>, 3> readVtkCoordinates(const VtkXmlFile& file, const VtkDataset& dataset,
                                                      std::uint64_t memoryCap);

// A structured grid's node positions over the whole extent, x fastest.
std::vector<glm::vec3> readVtkPoints(const VtkXmlFile& file, const VtkDataset& dataset, std::uint64_t memoryCap);

}  // namespace tstyles
