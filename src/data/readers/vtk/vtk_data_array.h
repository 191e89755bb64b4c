// A VTK <DataArray>: what it declares (name, type, components, where its data is), and its values
// read as one float per point: the array's only component, or the magnitude of a vector.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <pugixml.hpp>

#include "tstyles/data/series.h"
#include "vtk_xml_file.h"

namespace tstyles {

enum class VtkValueKind { Signed, Unsigned, Float };

struct VtkValueType {
    std::string name;  // as VTK writes it: "Float32", "UInt8", ...
    VtkValueKind kind = VtkValueKind::Float;
    std::size_t bytes = 4;
};

struct VtkDataArray {
    pugi::xml_node node;
    std::string name;
    VtkValueType type;
    std::uint64_t components = 1;
    std::string format;  // ascii, binary or appended
    std::uint64_t offset = 0;  // into the appended data
};

// The arrays of a <PointData>, <CellData> or <Points> element, each one checked: a known type, 1 to
// 64 components, a known format, an offset for appended data. `field` names the element in messages.
std::vector<VtkDataArray> describeArrays(const VtkXmlFile& file, const pugi::xml_node& parent);

// How the array's type is kept in the series: the same where ValueType has it, else Float64
// (UInt32, Int64, UInt64 become floats, as every value does on the way to density).
ValueType seriesValueType(const VtkValueType& type);

// What --var naming no point array says: the point arrays there are (`pointArrayList`, "none"
// when empty), and that `name` is a cell array where it is one. One wording for XML and legacy files.
std::string missingPointArrayProblem(const std::string& name, const std::string& pointArrayList,
                                     const std::vector<std::string>& cellArrays);

// One value of `type` from its bytes in the given byte order (VTK XML says which; legacy files are
// big-endian), as a double: exact for every type but 64-bit integers beyond 2^53.
double decodeVtkValue(const std::uint8_t* bytes, const VtkValueType& type, bool bigEndian);

// `tuples` values, one per point: the single component, or the Euclidean magnitude of all of them.
// The size is checked against the data (ascii: the count of numbers; binary: the headers) and
// against `memoryCap` before anything is allocated.
std::vector<float> readPointValues(const VtkXmlFile& file, const VtkDataArray& array, std::uint64_t tuples,
                                   std::uint64_t memoryCap);

// `tuples` 3-component points as (x, y, z) floats, for a structured grid's <Points>.
std::vector<float> readPointComponents(const VtkXmlFile& file, const VtkDataArray& array, std::uint64_t tuples,
                                       std::uint64_t memoryCap);

}  // namespace tstyles
