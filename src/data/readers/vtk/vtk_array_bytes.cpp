// VTK's binary array layouts (vtkXMLWriter): uncompressed, [byte count][bytes]; compressed,
// [block count][block size][last block size][compressed size of each block][blocks], every header
// integer of header_type in the file's byte order. Sizes are checked before anything is decoded.
#include "vtk_array_bytes.h"

#include <algorithm>

#include <lz4.h>
#include <lzma.h>
#include <zlib.h>

#include "../../value_decoding.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

// The most a compressed byte can expand to: deflate 1032 (RFC 1951), LZ4 255 (a 255-byte length
// run per byte at best), LZMA far more (long runs cost almost nothing), so its bound is set from
// what xz makes of zeros (about 1 : 7000), rounded up.
std::uint64_t maxExpansion(VtkCompressor compressor) {
    switch (compressor) {
        case VtkCompressor::ZLib: return 1032;
        case VtkCompressor::LZ4: return 256;
        case VtkCompressor::LZMA: return 16384;
        case VtkCompressor::None: break;
    }
    return 1;
}

// LZMA streams name a dictionary size the decoder allocates; VTK's presets need at most 65 MiB.
constexpr std::uint64_t kLzmaMemoryLimit = std::uint64_t(96) << 20;

// A block, packed or not, is handed to the decompressors whole, and LZ4 counts in int: VTK's own
// blocks are 32 KiB.
constexpr std::uint64_t kMaxBlockBytes = std::uint64_t(1) << 30;

struct ArrayContext {
    const std::filesystem::path& file;
    const std::string& field;
    [[noreturn]] void fail(const std::string& problem) const { throwInputError(file, field, problem); }
};

std::uint64_t readHeaderInteger(VtkByteStream& stream, const VtkBinaryLayout& layout, const ArrayContext& context,
                                const char* what) {
    std::uint8_t bytes[8] = {};
    if (!stream.read(bytes, layout.headerBytes))
        context.fail(std::string("is truncated: the data ends inside its header (") + what + ")" +
                     (*stream.failure() ? std::string(": ") + stream.failure() : std::string()));
    return decodeUnsigned(bytes, layout.headerBytes, layout.bigEndian ? ByteOrder::Big : ByteOrder::Little);
}

void readPayload(VtkByteStream& stream, std::uint8_t* out, std::size_t count, const ArrayContext& context,
                 const std::string& what) {
    if (!stream.read(out, count))
        context.fail("is truncated: " + what + " needs " + std::to_string(count) + " bytes, the data ends first" +
                     (*stream.failure() ? std::string(" (") + stream.failure() + ")" : std::string()));
}

void decompressBlock(VtkCompressor compressor, const std::vector<std::uint8_t>& packed, std::uint8_t* out,
                     std::size_t size, const ArrayContext& context, std::size_t block) {
    const std::string where = "block " + std::to_string(block) + " ";
    bool good = false;
    if (compressor == VtkCompressor::ZLib) {
        uLongf produced = uLongf(size);
        good = uncompress(out, &produced, packed.data(), uLong(packed.size())) == Z_OK && produced == size;
    } else if (compressor == VtkCompressor::LZ4) {
        good = LZ4_decompress_safe(reinterpret_cast<const char*>(packed.data()), reinterpret_cast<char*>(out),
                                   int(packed.size()), int(size)) == int(size);
    } else {
        std::uint64_t memoryLimit = kLzmaMemoryLimit;
        std::size_t inPosition = 0;
        std::size_t outPosition = 0;
        good = lzma_stream_buffer_decode(&memoryLimit, 0, nullptr, packed.data(), &inPosition, packed.size(), out,
                                         &outPosition, size) == LZMA_OK &&
               outPosition == size;
    }
    if (!good)
        context.fail("is corrupt: " + where + "does not decompress (" + toString(compressor) + ") to the " +
                     std::to_string(size) + " bytes its header gives");
}

// blocks - 1 full blocks and the last one make exactly the bytes expected (without overflow).
bool blockSizesAgree(std::uint64_t blocks, std::uint64_t blockSize, std::uint64_t last, std::uint64_t expected) {
    if (blocks == 0) return expected == 0;
    if (blockSize == 0 || blockSize > kMaxBlockBytes || last > blockSize || last > expected) return false;
    return blocks - 1 <= (expected - last) / blockSize && (blocks - 1) * blockSize + last == expected;
}

std::vector<std::uint8_t> readCompressed(VtkByteStream& stream, const VtkBinaryLayout& layout, std::uint64_t expected,
                                         const ArrayContext& context) {
    const std::uint64_t blocks = readHeaderInteger(stream, layout, context, "block count");
    const std::uint64_t blockSize = readHeaderInteger(stream, layout, context, "block size");
    const std::uint64_t lastSize = readHeaderInteger(stream, layout, context, "last block size");
    if (blocks > stream.bytesLeftAtMost() / layout.headerBytes)
        context.fail("is truncated: its header names " + std::to_string(blocks) +
                     " compressed blocks, more than the data can hold");
    // A full last block is written as size 0.
    const std::uint64_t last = lastSize == 0 ? blockSize : lastSize;
    if (!blockSizesAgree(blocks, blockSize, last, expected))
        context.fail("its compression header (" + std::to_string(blocks) + " blocks of " + std::to_string(blockSize) +
                     " bytes, the last " + std::to_string(lastSize) + ") disagrees with the " +
                     std::to_string(expected) + " bytes the extent and type need");
    std::vector<std::uint64_t> packedSizes(blocks);
    std::uint64_t packedTotal = 0;
    for (std::size_t block = 0; block < blocks; ++block) {
        const std::uint64_t packed = readHeaderInteger(stream, layout, context, "compressed block size");
        const std::uint64_t size = block + 1 == blocks ? last : blockSize;
        const bool fits = packed <= stream.bytesLeftAtMost() && packed <= kMaxBlockBytes &&
                          packed * maxExpansion(layout.compressor) >= size;
        if (!fits)
            context.fail("is truncated or corrupt: compressed block " + std::to_string(block) + " of " +
                         std::to_string(packed) + " bytes cannot hold " + std::to_string(size) + " bytes");
        packedSizes[block] = packed;
        packedTotal += packed;
    }
    if (packedTotal > stream.bytesLeftAtMost())
        context.fail("is truncated: its blocks need " + std::to_string(packedTotal) + " compressed bytes, the data has " +
                     std::to_string(stream.bytesLeftAtMost()));
    std::vector<std::uint8_t> bytes(expected);
    std::vector<std::uint8_t> packed;
    for (std::size_t block = 0; block < blocks; ++block) {
        packed.resize(packedSizes[block]);
        readPayload(stream, packed.data(), packed.size(), context, "compressed block " + std::to_string(block));
        const std::size_t size = block + 1 == blocks ? last : blockSize;
        decompressBlock(layout.compressor, packed, bytes.data() + block * blockSize, size, context, block);
    }
    return bytes;
}

}  // namespace

std::string toString(VtkCompressor compressor) {
    switch (compressor) {
        case VtkCompressor::ZLib: return "vtkZLibDataCompressor";
        case VtkCompressor::LZ4: return "vtkLZ4DataCompressor";
        case VtkCompressor::LZMA: return "vtkLZMADataCompressor";
        case VtkCompressor::None: break;
    }
    return "none";
}

std::vector<std::uint8_t> readVtkArrayBytes(VtkByteStream& stream, const VtkBinaryLayout& layout,
                                            std::uint64_t expected, const std::filesystem::path& file,
                                            const std::string& field) {
    const ArrayContext context{file, field};
    if (layout.compressor != VtkCompressor::None) return readCompressed(stream, layout, expected, context);
    const std::uint64_t count = readHeaderInteger(stream, layout, context, "byte count");
    if (count != expected)
        context.fail("its header gives " + std::to_string(count) + " bytes of data, the extent and type need " +
                     std::to_string(expected));
    if (expected > stream.bytesLeftAtMost())
        context.fail("is truncated: " + std::to_string(expected) + " bytes of data, the file holds at most " +
                     std::to_string(stream.bytesLeftAtMost()));
    std::vector<std::uint8_t> bytes(expected);
    readPayload(stream, bytes.data(), bytes.size(), context, "the array");
    return bytes;
}

}  // namespace tstyles
