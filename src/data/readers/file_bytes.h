// Reading a file's data bytes, raw or gzip-compressed, from an offset: exactly the bytes expected,
// or an InputError that says the file is truncated (or corrupt) and by how much.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tstyles {

enum class DataEncoding { Raw, Gzip };

// Whether a gzip stream may hold more than the bytes expected (the Isabel files must hold exactly
// one volume: more means the dims are wrong).
enum class TrailingData { Allowed, Refused };

// `expected` bytes starting `offset` bytes into the file (for gzip: into the compressed file, the
// count being of uncompressed bytes). `what` describes the data for messages ("NRRD data").
std::vector<std::uint8_t> readDataBytes(const std::filesystem::path& file, std::uint64_t offset,
                                        std::size_t expected, DataEncoding encoding, const std::string& what,
                                        TrailingData trailing = TrailingData::Allowed);

// An InputError saying "truncated" unless `file` is a regular file that can hold `expected` bytes
// from `offset`: raw, the bytes themselves; gzip, as many compressed bytes as deflate needs at its
// best ratio. Checked when a file is opened, before any memory is taken for its data.
void requireDataInFile(const std::filesystem::path& file, std::uint64_t offset, double expected,
                       DataEncoding encoding, const std::string& what);

// True when the file starts with the gzip magic bytes.
bool isGzipFile(const std::filesystem::path& file);

}  // namespace tstyles
