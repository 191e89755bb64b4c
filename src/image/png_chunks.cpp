// PNG chunk lengths against the file size (png_chunks.h). A chunk: 4-byte big-endian length, 4-byte
// type, the data, a 4-byte CRC.
#include "png_chunks.h"

#include <array>
#include <fstream>
#include <string>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

constexpr std::array<unsigned char, 8> kPngSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr std::uint64_t kChunkOverhead = 12;  // length, type, CRC

std::uint32_t bigEndian32(const unsigned char* bytes) {
    return std::uint32_t(bytes[0]) << 24 | std::uint32_t(bytes[1]) << 16 | std::uint32_t(bytes[2]) << 8 |
           std::uint32_t(bytes[3]);
}

// Printable chunk types as they are ("tEXt"), others as "?".
std::string chunkName(const unsigned char* type) {
    std::string name;
    for (int index = 0; index < 4; ++index)
        name += (type[index] >= 0x20 && type[index] < 0x7f) ? char(type[index]) : '?';
    return name;
}

}  // namespace

void requirePngChunksInsideFile(const std::filesystem::path& file, std::uint64_t fileSize) {
    std::ifstream stream(file, std::ios::binary);
    std::array<unsigned char, 8> bytes{};
    if (!stream.read(reinterpret_cast<char*>(bytes.data()), bytes.size()) || bytes != kPngSignature) return;
    std::uint64_t offset = kPngSignature.size();
    // Each pass moves at least 12 bytes on, so the walk ends within fileSize / 12 chunks.
    while (offset + 8 <= fileSize) {
        stream.seekg(std::streamoff(offset));
        if (!stream.read(reinterpret_cast<char*>(bytes.data()), 8)) return;  // libpng says what is wrong
        const std::uint64_t length = bigEndian32(bytes.data());
        const std::string name = chunkName(bytes.data() + 4);
        // The PNG specification caps a chunk at 2^31 - 1 bytes.
        if (length > 0x7fffffffu || offset + kChunkOverhead + length > fileSize)
            throwInputError(file, "PNG chunk '" + name + "' at byte " + std::to_string(offset),
                            "says " + std::to_string(length) + " bytes of data, but the file has " +
                                std::to_string(fileSize > offset + kChunkOverhead ? fileSize - offset - kChunkOverhead : 0) +
                                " left after it (truncated or damaged)");
        if (name == "IEND") return;
        offset += kChunkOverhead + length;
    }
}

}  // namespace tstyles
