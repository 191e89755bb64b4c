// Limits that an input file or option cannot push us past: the memory a dataset or image may take
// (a share of the machine's memory unless --max-memory says otherwise), regular files only, and
// sizes checked against what a file holds before anything is allocated for it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace tstyles {

// Half of the physical memory (sysconf), the cap when no --max-memory is given: a dataset that
// needs more would swap the machine to a halt before failing.
std::uint64_t defaultMemoryCap();

// The cap in force: the one given, else defaultMemoryCap().
std::uint64_t memoryCap(const std::optional<std::uint64_t>& given);

// "512 bytes", "3.5 KiB", "1.2 GiB": figures in messages.
std::string byteCountText(double bytes);

// An InputError naming `file` and `field` unless `bytes` fit under `cap`; `what` says what needs
// them ("the pixels of a 100000 x 100000 image").
void requireMemory(const std::filesystem::path& file, const std::string& field, double bytes, std::uint64_t cap,
                   const std::string& what);

// An InputError unless `file` is a regular file (not a folder, device, FIFO or socket, which would
// block or never end); `what` names it in the message ("style image", "NetCDF file").
void requireRegularFile(const std::filesystem::path& file, const std::string& what);

// The size of a regular file, as requireRegularFile checks it.
std::uint64_t regularFileSize(const std::filesystem::path& file, const std::string& what);

}  // namespace tstyles
