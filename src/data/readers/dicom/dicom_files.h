// Finding DICOM files: the DICM magic, the files of a folder (nested folders included, within
// limits), and whether a folder is a DICOM folder at all (a cheap look at its first few files).
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

namespace tstyles {

// Limits of a folder walk: scanners nest a study a few folders deep, never dozens.
inline constexpr int kMaxDicomFolderDepth = 8;
inline constexpr std::size_t kMaxDicomFiles = 100000;

// True when the file holds "DICM" at byte 128 (the DICOM Part 10 preamble and magic).
bool hasDicomMagic(const std::filesystem::path& file);

// A folder that holds a DICOM file among the first few files found (looking two levels down), and
// no series.json (a manifest's folder).
bool isDicomFolder(const std::filesystem::path& folder);

struct DicomFileList {
    std::vector<std::filesystem::path> files;  // sorted by path
    std::size_t skipped = 0;                   // regular files without the magic (README, DICOMDIR-less thumbnails)
};

// Every regular file with the DICM magic under `folder`, DICOMDIR left out (the files it indexes are
// found by the walk itself). More than kMaxDicomFiles files, or nesting deeper than
// kMaxDicomFolderDepth, is an InputError naming the folder.
DicomFileList dicomFilesUnder(const std::filesystem::path& folder);

}  // namespace tstyles
