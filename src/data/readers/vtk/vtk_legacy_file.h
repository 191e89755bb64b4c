// A legacy VTK file (.vtk): STRUCTURED_POINTS, STRUCTURED_GRID or RECTILINEAR_GRID, ASCII or
// BINARY (big-endian, as the legacy format always is), versions 2.0 to 5.1. docs/readers/vtk-xml.md.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "vtk_data_array.h"  // VtkValueType, VtkValueKind
#include "vtk_dataset.h"     // VtkGridKind

namespace tstyles {

struct VtkLegacyArray {
    std::string name;
    VtkValueType type;             // in the XML spelling ("Float32", "UInt8", ...), kind and bytes set
    // SCALARS numComp (default 1), VECTORS/NORMALS 3, TENSORS 9, FIELD arrays their numComp.
    std::uint64_t components = 1;
    std::uint64_t start = 0;       // byte offset in the file where its values begin
};

struct VtkLegacyFile {
    std::filesystem::path path;
    std::string title;  // the second line
    bool binary = false;
    VtkGridKind kind = VtkGridKind::Image;
    glm::ivec3 dims{0};      // DIMENSIONS
    glm::dvec3 origin{0.0};  // STRUCTURED_POINTS ORIGIN
    glm::dvec3 spacing{1.0};  // STRUCTURED_POINTS SPACING (or ASPECT_RATIO, its old name)
    // POINT_DATA: SCALARS, COLOR_SCALARS, VECTORS, NORMALS, TEXTURE_COORDINATES, TENSORS, FIELD arrays.
    std::vector<VtkLegacyArray> pointArrays;
    std::string activeScalars;            // the name of the first SCALARS array of POINT_DATA (empty if none)
    std::vector<std::string> cellArrays;  // names of CELL_DATA arrays: described (skipped), never read
    VtkLegacyArray points;                // STRUCTURED_GRID's POINTS (3 components)
    std::array<VtkLegacyArray, 3> coordinates;  // RECTILINEAR_GRID's X_ Y_ Z_COORDINATES (1 component each)
};

// Reads the file's structure: the header, the dataset's geometry keywords and every array's name,
// type, components and where its values start, skipping over the values (binary: by their size;
// ASCII: by counting the numbers). Every problem is an InputError naming the file and the keyword
// (e.g. field "DIMENSIONS", "SCALARS temperature", "POINT_DATA") and what is wrong: not a legacy
// VTK file, an unsupported DATASET, a point count that disagrees with DIMENSIONS, an unknown type,
// an array whose values run past the end of the file (truncated), a bad number, a count not
// matching. `memoryCap` bounds what is allocated.
VtkLegacyFile describeVtkLegacyFile(const std::filesystem::path& path, std::uint64_t memoryCap);

// One float per point of the point array `name` (product of dims values, x fastest): its only
// component, or the Euclidean magnitude of all of them (as readPointValues in vtk_data_array.h does
// for XML). InputError if there is no such point array (listing those there are; if it is a cell
// array, saying only point arrays are read).
std::vector<float> readVtkLegacyPointArray(const VtkLegacyFile& file, const std::string& name, std::uint64_t memoryCap);

// RECTILINEAR_GRID: the x, y, z coordinates (each must be finite and increase strictly).
std::array<std::vector<double>, 3> readVtkLegacyCoordinates(const VtkLegacyFile& file, std::uint64_t memoryCap);

// STRUCTURED_GRID: the POINTS, x fastest.
std::vector<glm::vec3> readVtkLegacyPoints(const VtkLegacyFile& file, std::uint64_t memoryCap);

// "STRUCTURED_POINTS", "RECTILINEAR_GRID", "STRUCTURED_GRID": the DATASET keyword's spelling.
std::string legacyDatasetName(VtkGridKind kind);

// Whether the file starts with "# vtk DataFile Version" (the format table's content sniff).
bool looksLikeVtkLegacy(const std::filesystem::path& path);

}  // namespace tstyles
