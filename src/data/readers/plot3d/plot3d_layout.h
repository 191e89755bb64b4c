// The binary layout of a Plot3D file, found by trying every combination of byte order, Fortran
// record markers, single/multi-block header, precision and IBLANK against the file's size.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tstyles {

// Grid files (.xyz), solution files (.q: five flow variables) and function files (.f: any number
// of variables per block, the count stored with each block's dims).
enum class Plot3DKind { GridFile, SolutionFile, FunctionFile };

struct Plot3DLayout {
    bool bigEndian = false;
    bool records = false;     // Fortran unformatted: every record framed by 4-byte lengths
    bool multiBlock = false;  // a block count before the dims
    int precision = 4;        // bytes per real
    bool iblank = false;      // grid files: an int per node after x, y, z
    std::vector<glm::ivec3> dims;  // per block
    std::vector<int> functionCounts;  // function files: variables per block
    // Byte offset of each block's data: for grids the x array (y, z, IBLANK follow); for solutions
    // the four reals (mach, alpha, Reynolds number, time), then (next offset) the five q arrays;
    // for function files the first variable's array (the others follow).
    std::vector<std::size_t> blockOffsets;
    std::vector<std::size_t> solutionArrayOffsets;

    std::string describe() const;
};

// The whole file and its layout. Throws InputError naming the file when no layout fits.
struct Plot3DFile {
    std::filesystem::path path;
    std::vector<std::uint8_t> bytes;
    Plot3DLayout layout;

    std::int32_t integer(std::size_t offset) const;
    double real(std::size_t offset) const;  // at layout.precision
};

Plot3DFile readPlot3DFile(const std::filesystem::path& path, Plot3DKind kind);

}  // namespace tstyles
