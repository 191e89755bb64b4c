// Each codec checks the sizes its stream claims against the chunk's size before it writes a byte:
// a chunk file is input like any other and may lie about what it holds.
#include "zarr_codecs.h"

#include <array>
#include <cstring>

#include <blosc.h>
#include <lz4.h>
#include <zlib.h>
#include <zstd.h>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

[[noreturn]] void refuseChunk(const std::filesystem::path& chunkFile, ZarrByteCodec codec, const std::string& problem) {
    throwInputError(chunkFile, toString(codec), "the chunk " + problem);
}

std::string sizeText(std::size_t found, std::size_t expected) {
    return std::to_string(found) + " bytes where the chunk holds " + std::to_string(expected);
}

std::vector<std::uint8_t> decodeBlosc(const std::vector<std::uint8_t>& stored, std::size_t expected,
                                      const std::filesystem::path& chunkFile) {
    std::size_t claimed = 0;
    // blosc_cbuffer_validate reads the header only after checking there is one, and checks that the
    // compressed size it states fits in the bytes given.
    if (blosc_cbuffer_validate(stored.data(), stored.size(), &claimed) != 0)
        refuseChunk(chunkFile, ZarrByteCodec::Blosc, "is not a whole blosc buffer (cut short or damaged)");
    if (claimed != expected) refuseChunk(chunkFile, ZarrByteCodec::Blosc, "decompresses to " + sizeText(claimed, expected));
    std::vector<std::uint8_t> bytes(expected);
    const int written = blosc_decompress_ctx(stored.data(), bytes.data(), bytes.size(), 1);
    if (written < 0 || std::size_t(written) != expected)
        refuseChunk(chunkFile, ZarrByteCodec::Blosc, "is damaged: blosc could not decompress it");
    return bytes;
}

// windowBits 47: a zlib or a gzip stream, whichever the header says (numcodecs' Zlib writes zlib,
// GZip and Zarr v3's gzip write gzip).
std::vector<std::uint8_t> decodeDeflate(const std::vector<std::uint8_t>& stored, std::size_t expected,
                                        const std::filesystem::path& chunkFile, ZarrByteCodec codec) {
    std::vector<std::uint8_t> bytes(expected);
    z_stream stream{};
    if (inflateInit2(&stream, 47) != Z_OK) throw std::bad_alloc();
    stream.next_in = const_cast<Bytef*>(stored.data());
    stream.avail_in = uInt(stored.size());
    // One more byte of room than expected, so a stream holding more than the chunk is seen.
    std::uint8_t overflow = 0;
    stream.next_out = bytes.data();
    stream.avail_out = uInt(bytes.size());
    int status = inflate(&stream, Z_FINISH);
    if (status == Z_BUF_ERROR && stream.avail_out == 0 && stream.avail_in > 0) {
        stream.next_out = &overflow;
        stream.avail_out = 1;
        status = inflate(&stream, Z_FINISH);
    }
    const std::size_t written = stream.total_out;
    inflateEnd(&stream);
    if (status == Z_STREAM_END && written == expected) return bytes;
    if (status == Z_DATA_ERROR || status == Z_NEED_DICT) refuseChunk(chunkFile, codec, "is damaged: not a valid deflate stream");
    if (written > expected) refuseChunk(chunkFile, codec, "decompresses to more than the " + std::to_string(expected) + " bytes it holds");
    refuseChunk(chunkFile, codec, "is cut short: it decompresses to " + sizeText(written, expected));
}

std::vector<std::uint8_t> decodeZstd(const std::vector<std::uint8_t>& stored, std::size_t expected,
                                     const std::filesystem::path& chunkFile) {
    const unsigned long long claimed = ZSTD_getFrameContentSize(stored.data(), stored.size());
    if (claimed == ZSTD_CONTENTSIZE_ERROR) refuseChunk(chunkFile, ZarrByteCodec::Zstd, "is not a zstd frame");
    if (claimed != ZSTD_CONTENTSIZE_UNKNOWN && claimed != expected)
        refuseChunk(chunkFile, ZarrByteCodec::Zstd, "decompresses to " + sizeText(std::size_t(claimed), expected));
    std::vector<std::uint8_t> bytes(expected);
    const std::size_t written = ZSTD_decompress(bytes.data(), bytes.size(), stored.data(), stored.size());
    if (ZSTD_isError(written))
        refuseChunk(chunkFile, ZarrByteCodec::Zstd, std::string("is cut short or damaged: ") + ZSTD_getErrorName(written));
    if (written != expected) refuseChunk(chunkFile, ZarrByteCodec::Zstd, "decompresses to " + sizeText(written, expected));
    return bytes;
}

// numcodecs' LZ4: the uncompressed size as 4 little-endian bytes, then one LZ4 block.
std::vector<std::uint8_t> decodeLz4(const std::vector<std::uint8_t>& stored, std::size_t expected,
                                    const std::filesystem::path& chunkFile) {
    if (stored.size() < 4) refuseChunk(chunkFile, ZarrByteCodec::Lz4, "is cut short: it lacks the 4-byte size");
    const std::size_t claimed = std::size_t(stored[0]) | std::size_t(stored[1]) << 8 | std::size_t(stored[2]) << 16 |
                                std::size_t(stored[3]) << 24;
    if (claimed != expected) refuseChunk(chunkFile, ZarrByteCodec::Lz4, "decompresses to " + sizeText(claimed, expected));
    if (expected > std::size_t(LZ4_MAX_INPUT_SIZE) || stored.size() - 4 > std::size_t(LZ4_MAX_INPUT_SIZE))
        refuseChunk(chunkFile, ZarrByteCodec::Lz4, "is larger than one LZ4 block can be");
    std::vector<std::uint8_t> bytes(expected);
    const int written = LZ4_decompress_safe(reinterpret_cast<const char*>(stored.data() + 4),
                                            reinterpret_cast<char*>(bytes.data()), int(stored.size() - 4), int(expected));
    if (written < 0 || std::size_t(written) != expected)
        refuseChunk(chunkFile, ZarrByteCodec::Lz4, "is cut short or damaged: LZ4 could not decompress it");
    return bytes;
}

void stripCrc32c(std::vector<std::uint8_t>& stored, const std::filesystem::path& chunkFile) {
    if (stored.size() < 4) refuseChunk(chunkFile, ZarrByteCodec::Crc32c, "is cut short: it lacks its 4-byte checksum");
    const std::size_t body = stored.size() - 4;
    const std::uint32_t written = std::uint32_t(stored[body]) | std::uint32_t(stored[body + 1]) << 8 |
                                  std::uint32_t(stored[body + 2]) << 16 | std::uint32_t(stored[body + 3]) << 24;
    if (crc32c(stored.data(), body) != written)
        refuseChunk(chunkFile, ZarrByteCodec::Crc32c, "is damaged: its CRC-32C checksum does not match");
    stored.resize(body);
}

}  // namespace

std::string toString(ZarrByteCodec codec) {
    switch (codec) {
        case ZarrByteCodec::Blosc: return "blosc";
        case ZarrByteCodec::Zlib: return "zlib";
        case ZarrByteCodec::Gzip: return "gzip";
        case ZarrByteCodec::Zstd: return "zstd";
        case ZarrByteCodec::Lz4: return "lz4";
        case ZarrByteCodec::Crc32c: return "crc32c";
    }
    return "unknown";
}

std::uint32_t crc32c(const std::uint8_t* bytes, std::size_t size) {
    // The reflected Castagnoli polynomial, one table built once per call: chunks are few and the
    // table is 1 KiB, so no state outlives the call.
    std::array<std::uint32_t, 256> table{};
    for (std::uint32_t entry = 0; entry < 256; ++entry) {
        std::uint32_t value = entry;
        for (int bit = 0; bit < 8; ++bit) value = (value >> 1) ^ (value & 1u ? 0x82F63B78u : 0u);
        table[entry] = value;
    }
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::size_t index = 0; index < size; ++index) crc = (crc >> 8) ^ table[(crc ^ bytes[index]) & 0xFFu];
    return crc ^ 0xFFFFFFFFu;
}

std::vector<std::uint8_t> decodeChunkBytes(std::vector<std::uint8_t> stored, const std::vector<ZarrByteCodec>& codecs,
                                           std::size_t expected, const std::filesystem::path& chunkFile) {
    for (auto codec = codecs.rbegin(); codec != codecs.rend(); ++codec) {
        switch (*codec) {
            case ZarrByteCodec::Crc32c: stripCrc32c(stored, chunkFile); break;
            case ZarrByteCodec::Blosc: stored = decodeBlosc(stored, expected, chunkFile); break;
            case ZarrByteCodec::Zlib:
            case ZarrByteCodec::Gzip: stored = decodeDeflate(stored, expected, chunkFile, *codec); break;
            case ZarrByteCodec::Zstd: stored = decodeZstd(stored, expected, chunkFile); break;
            case ZarrByteCodec::Lz4: stored = decodeLz4(stored, expected, chunkFile); break;
        }
    }
    if (stored.size() != expected)
        throwInputError(chunkFile, "", "decodes to " + sizeText(stored.size(), expected) +
                                           (stored.size() < expected ? " (cut short)" : ""));
    return stored;
}

}  // namespace tstyles
