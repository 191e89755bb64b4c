// Legacy VTK files (src/data/readers/vtk/vtk_legacy_file.h) written here as text and big-endian bytes:
// exact values of ASCII and BINARY arrays, vectors as magnitudes, the grids' coordinates and points,
// and refusals that name the keyword and the problem.
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "readers/vtk/vtk_legacy_file.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

constexpr std::uint64_t kCap = 1 << 30;

std::filesystem::path writeFile(const std::string& name, const std::string& bytes) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "tstyles_vtk_legacy_test";
    std::filesystem::create_directories(folder);
    const std::filesystem::path file = folder / name;
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
}

// `value`'s bytes, most significant first, as every legacy binary file holds them.
template <class T>
std::string bigEndian(T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    std::string text(bytes, sizeof(T));
    if constexpr (std::endian::native == std::endian::little) return {text.rbegin(), text.rend()};
    return text;
}

template <class T>
std::string bigEndianValues(std::initializer_list<T> values) {
    std::string bytes;
    for (const T value : values) bytes += bigEndian(value);
    return bytes;
}

// The InputError's message, or a failure when there is none.
std::string refusal(const std::function<void()>& read) {
    try {
        read();
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no InputError";
    return "";
}

void expectRefusal(const std::filesystem::path& file, const std::string& field, const std::string& problem,
                   const std::function<void()>& read) {
    const std::string message = refusal(read);
    EXPECT_NE(message.find(file.string() + ": " + (field.empty() ? "" : field + ": ")), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
}

const std::string kHeader = "# vtk DataFile Version 5.1\nknown values\n";

// 2 x 2 x 2 points: a dataset FIELD (not point data), cell data, scalars with a lookup table and a
// table section, a vector, and a FIELD with a component-named array (5.1's METADATA block).
const std::string kAscii = kHeader +
                           "ASCII\n"
                           "DATASET STRUCTURED_POINTS\n"
                           "FIELD FieldData 1\n"
                           "TIME 1 1 double\n"
                           "3.5\n"
                           "DIMENSIONS 2 2 2\n"
                           "SPACING 0.5 1 2\n"
                           "ORIGIN 1 -2 3\n"
                           "CELL_DATA 1\n"
                           "SCALARS cellv float\n"
                           "LOOKUP_TABLE default\n"
                           "7\n"
                           "POINT_DATA 8\n"
                           "scalars density float 1\n"
                           "LOOKUP_TABLE colours\n"
                           "0.5 -1.25 2 1e3\n"
                           "nan 6 +7 8\n"
                           "LOOKUP_TABLE colours 2\n"
                           "0 0 0 1 1 1 1 1\n"
                           "VECTORS wind float\n"
                           "3 4 0 5 12 0 0 0 0 1 0 0\n"
                           "0 0 -2 6 8 0 0 3 4 2 3 6\n"
                           "FIELD FieldData 2\n"
                           "my%20label 1 8 unsigned_char\n"
                           "0 1 2 3 4 5 6 255\n"
                           "METADATA\n"
                           "COMPONENT_NAMES\n"
                           "first\n"
                           "\n"
                           "NULL_ARRAY\n";

TEST(VtkLegacyFile, ReadsAnAsciiFileExactly) {
    const auto path = writeFile("ascii.vtk", kAscii);
    ASSERT_TRUE(looksLikeVtkLegacy(path));
    const VtkLegacyFile file = describeVtkLegacyFile(path, kCap);
    EXPECT_EQ(file.title, "known values");
    EXPECT_FALSE(file.binary);
    EXPECT_EQ(file.kind, VtkGridKind::Image);
    EXPECT_EQ(file.dims, glm::ivec3(2, 2, 2));
    EXPECT_EQ(file.origin, glm::dvec3(1.0, -2.0, 3.0));
    EXPECT_EQ(file.spacing, glm::dvec3(0.5, 1.0, 2.0));
    EXPECT_EQ(file.activeScalars, "density");
    ASSERT_EQ(file.pointArrays.size(), 3u) << "the dataset's FIELD (TIME) is no point array";
    EXPECT_EQ(file.pointArrays[0].type.name, "Float32");
    EXPECT_EQ(file.pointArrays[1].components, 3u);
    EXPECT_EQ(file.pointArrays[2].name, "my label") << "%20 is a space";
    EXPECT_EQ(file.pointArrays[2].type.name, "UInt8");
    EXPECT_EQ(file.cellArrays, std::vector<std::string>{"cellv"});

    const std::vector<float> density = readVtkLegacyPointArray(file, "density", kCap);
    ASSERT_EQ(density.size(), 8u);
    const std::vector<float> expected{0.5f, -1.25f, 2.0f, 1000.0f, 0.0f, 6.0f, 7.0f, 8.0f};
    for (std::size_t index = 0; index < 8; ++index)
        if (index == 4) EXPECT_TRUE(std::isnan(density[index])) << "nan means a missing value";
        else EXPECT_EQ(density[index], expected[index]) << index;
    EXPECT_EQ(readVtkLegacyPointArray(file, "my label", kCap),
              (std::vector<float>{0, 1, 2, 3, 4, 5, 6, 255}));
}

TEST(VtkLegacyFile, ReadsVectorsAsTheirMagnitudes) {
    const VtkLegacyFile file = describeVtkLegacyFile(writeFile("vectors.vtk", kAscii), kCap);
    EXPECT_EQ(readVtkLegacyPointArray(file, "wind", kCap), (std::vector<float>{5, 13, 0, 1, 2, 10, 5, 7}));
}

TEST(VtkLegacyFile, ReadsBigEndianBinaryValuesExactly) {
    const std::string bytes = kHeader + "BINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\nPOINT_DATA 8\n" +
                              "SCALARS count short\nLOOKUP_TABLE default\n" +
                              bigEndianValues<std::int16_t>({-300, 0, 1, 2, 10, 32767, -32768, 7}) + "\n" +
                              "FIELD FieldData 1\nspeed 1 8 float\n" +
                              bigEndianValues<float>({0.1f, -2.5f, 1e30f, 0.0f, 10.0f, 1.0f / 3.0f, 255.0f, -0.0f}) +
                              "\n";
    const VtkLegacyFile file = describeVtkLegacyFile(writeFile("binary.vtk", bytes), kCap);
    EXPECT_TRUE(file.binary);
    EXPECT_EQ(file.pointArrays[0].type.name, "Int16");
    EXPECT_EQ(readVtkLegacyPointArray(file, "count", kCap),
              (std::vector<float>{-300, 0, 1, 2, 10, 32767, -32768, 7}));
    EXPECT_EQ(readVtkLegacyPointArray(file, "speed", kCap),
              (std::vector<float>{0.1f, -2.5f, 1e30f, 0.0f, 10.0f, 1.0f / 3.0f, 255.0f, -0.0f}));
}

TEST(VtkLegacyFile, ReadsRectilinearCoordinates) {
    const std::string text = kHeader + "ASCII\nDATASET RECTILINEAR_GRID\nDIMENSIONS 2 3 2\n" +
                             "X_COORDINATES 2 float\n10 10.5\nY_COORDINATES 3 double\n-2 0 0.125\n" +
                             "Z_COORDINATES 2 int\n0 100\nPOINT_DATA 12\nSCALARS t float\nLOOKUP_TABLE default\n" +
                             "0 1 2 3 4 5 6 7 8 9 10 11\n";
    const VtkLegacyFile file = describeVtkLegacyFile(writeFile("rectilinear.vtk", text), kCap);
    EXPECT_EQ(file.kind, VtkGridKind::Rectilinear);
    const auto coordinates = readVtkLegacyCoordinates(file, kCap);
    EXPECT_EQ(coordinates[0], (std::vector<double>{10.0, 10.5}));
    EXPECT_EQ(coordinates[1], (std::vector<double>{-2.0, 0.0, 0.125}));
    EXPECT_EQ(coordinates[2], (std::vector<double>{0.0, 100.0}));
    EXPECT_EQ(readVtkLegacyPointArray(file, "t", kCap).back(), 11.0f);
}

TEST(VtkLegacyFile, ReadsStructuredGridPoints) {
    std::string points;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) points += bigEndianValues<double>({i + 0.25 * j, double(j), 2.0 * k});
    const std::string bytes =
        kHeader + "BINARY\nDATASET STRUCTURED_GRID\nDIMENSIONS 2 2 2\nPOINTS 8 double\n" + points + "\n";
    const VtkLegacyFile file = describeVtkLegacyFile(writeFile("grid.vtk", bytes), kCap);
    EXPECT_EQ(file.kind, VtkGridKind::Structured);
    const std::vector<glm::vec3> read = readVtkLegacyPoints(file, kCap);
    ASSERT_EQ(read.size(), 8u);
    EXPECT_EQ(read[0], glm::vec3(0, 0, 0));
    EXPECT_EQ(read[3], glm::vec3(1.25f, 1, 0));
    EXPECT_EQ(read[6], glm::vec3(0.25f, 1, 2));
}

TEST(VtkLegacyFile, RefusesTruncatedBinaryValues) {
    const auto path = writeFile("truncated.vtk", kHeader +
                                                     "BINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\n"
                                                     "POINT_DATA 8\nSCALARS density float\nLOOKUP_TABLE default\n" +
                                                     bigEndianValues<float>({1, 2, 3}));
    expectRefusal(path, "SCALARS density", "is truncated: its values need 32 bytes",
                  [&] { describeVtkLegacyFile(path, kCap); });
}

TEST(VtkLegacyFile, RefusesAPointCountThatDisagreesWithDimensions) {
    const auto path = writeFile("count.vtk", kHeader + "ASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\n"
                                                       "POINT_DATA 9\nSCALARS t float\n1 2 3 4 5 6 7 8 9\n");
    expectRefusal(path, "POINT_DATA", "9 points disagree with DIMENSIONS 2 x 2 x 2, which make 8",
                  [&] { describeVtkLegacyFile(path, kCap); });
}

TEST(VtkLegacyFile, RefusesDatasetsOtherThanTheStructuredOnes) {
    const auto path = writeFile("poly.vtk", kHeader + "ASCII\nDATASET POLYDATA\nPOINTS 1 float\n0 0 0\n");
    expectRefusal(path, "DATASET", "'POLYDATA' is not read: only STRUCTURED_POINTS, STRUCTURED_GRID and "
                                   "RECTILINEAR_GRID",
                  [&] { describeVtkLegacyFile(path, kCap); });
    const auto text = writeFile("text.vtk", "<VTKFile type=\"ImageData\">\n");
    EXPECT_FALSE(looksLikeVtkLegacy(text));
    expectRefusal(text, "", "not a legacy VTK file", [&] { describeVtkLegacyFile(text, kCap); });
}

TEST(VtkLegacyFile, RefusesUnknownTypesAndBadNumbers) {
    const std::string start = kHeader + "ASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\nPOINT_DATA 8\n";
    const auto quad = writeFile("quad.vtk", start + "SCALARS t quad\n1 2 3 4 5 6 7 8\n");
    expectRefusal(quad, "SCALARS t", "unknown type 'quad'", [&] { describeVtkLegacyFile(quad, kCap); });
    const auto bad = writeFile("bad.vtk", start + "SCALARS t float\n1 2 3 4.5.6 5 6 7 8\n");
    expectRefusal(bad, "SCALARS t", "'4.5.6' is not a number (number 4 of 8)",
                  [&] { describeVtkLegacyFile(bad, kCap); });
    const auto few = writeFile("few.vtk", start + "SCALARS t float\n1 2 3 4 5 6 7\nVECTORS v float\n");
    expectRefusal(few, "SCALARS t", "'VECTORS' is not a number (number 8 of 8)",
                  [&] { describeVtkLegacyFile(few, kCap); });
}

TEST(VtkLegacyFile, RefusesCoordinatesThatDoNotIncrease) {
    const auto path = writeFile("decreasing.vtk", kHeader + "ASCII\nDATASET RECTILINEAR_GRID\nDIMENSIONS 2 2 2\n"
                                                            "X_COORDINATES 2 float\n0 1\nY_COORDINATES 2 float\n0 1\n"
                                                            "Z_COORDINATES 2 float\n3 1\n");
    const VtkLegacyFile file = describeVtkLegacyFile(path, kCap);
    expectRefusal(path, "Z_COORDINATES", "the z coordinates must increase strictly: 1 follows 3",
                  [&] { readVtkLegacyCoordinates(file, kCap); });
}

TEST(VtkLegacyFile, NamesThePointArraysWhenOneIsMissing) {
    const auto path = writeFile("missing.vtk", kAscii);
    const VtkLegacyFile file = describeVtkLegacyFile(path, kCap);
    expectRefusal(path, "--var",
                  "no point array named 'pressure'; the point arrays are: density, wind (3 components), my label",
                  [&] { readVtkLegacyPointArray(file, "pressure", kCap); });
    expectRefusal(path, "--var", "'cellv' is a cell array: only point arrays are read",
                  [&] { readVtkLegacyPointArray(file, "cellv", kCap); });
}

}  // namespace
}  // namespace tstyles
