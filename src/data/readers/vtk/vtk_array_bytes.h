// One VTK DataArray's binary payload: the size header (UInt32 or UInt64) and, when the file names a
// compressor, the block header and the zlib, LZ4 or LZMA blocks behind it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "vtk_byte_stream.h"

namespace tstyles {

enum class VtkCompressor { None, ZLib, LZ4, LZMA };

// What the <VTKFile> element says of every binary array in the file.
struct VtkBinaryLayout {
    bool bigEndian = false;
    std::size_t headerBytes = 4;  // header_type UInt32 or UInt64
    VtkCompressor compressor = VtkCompressor::None;
};

std::string toString(VtkCompressor compressor);  // the name VTK writes: "vtkZLibDataCompressor", ...

// Exactly `expected` bytes of the array (still in the file's byte order), or an InputError naming
// `file` and `field` when a header disagrees with `expected`, does not fit in the data that is there,
// or a block does not decompress to the size its header gives. Nothing is allocated for a size the
// data cannot hold.
std::vector<std::uint8_t> readVtkArrayBytes(VtkByteStream& stream, const VtkBinaryLayout& layout,
                                            std::uint64_t expected, const std::filesystem::path& file,
                                            const std::string& field);

}  // namespace tstyles
