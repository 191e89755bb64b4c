// The folder walk behind a DICOM folder: bounded in depth and file count, and symbolic links to
// folders not followed, so that a loop or a whole disk cannot be walked by accident.
#include "dicom_files.h"

#include <algorithm>
#include <string>

#include "dicom_directory.h"
#include "../file_magic.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

bool isRegularFile(const std::filesystem::directory_entry& entry) {
    std::error_code error;
    return entry.is_regular_file(error);
}

bool isFolder(const std::filesystem::directory_entry& entry) {
    std::error_code error;
    return entry.is_directory(error) && !entry.is_symlink(error);
}

// Looks at no more than `budget` entries in all, `depth` levels down.
bool findsDicomFile(const std::filesystem::path& folder, int depth, int& budget) {
    std::error_code error;
    std::filesystem::directory_iterator entries(folder, error);
    if (error) return false;
    std::vector<std::filesystem::path> subfolders;
    for (const auto& entry : entries) {
        if (--budget < 0) return false;
        if (isRegularFile(entry) && !isDicomDirectoryFile(entry.path()) && hasDicomMagic(entry.path())) return true;
        if (isFolder(entry) && subfolders.size() < 4) subfolders.push_back(entry.path());
    }
    if (depth == 0) return false;
    return std::any_of(subfolders.begin(), subfolders.end(),
                       [&](const auto& subfolder) { return findsDicomFile(subfolder, depth - 1, budget); });
}

void collect(const std::filesystem::path& root, const std::filesystem::path& folder, int depth, DicomFileList& list) {
    if (depth > kMaxDicomFolderDepth)
        throwInputError(root, "", "nests folders more than " + std::to_string(kMaxDicomFolderDepth) +
                                      " deep: give the series' own folder");
    std::error_code error;
    std::filesystem::directory_iterator entries(folder, error);
    if (error) throwInputError(folder, "", "cannot list the folder: " + error.message());
    for (const auto& entry : entries) {
        if (isFolder(entry)) {
            collect(root, entry.path(), depth + 1, list);
        } else if (isRegularFile(entry) && !isDicomDirectoryFile(entry.path())) {
            if (!hasDicomMagic(entry.path())) {
                ++list.skipped;
                continue;
            }
            if (list.files.size() >= kMaxDicomFiles)
                throwInputError(root, "", "holds more than " + std::to_string(kMaxDicomFiles) +
                                              " DICOM files: give the series' own folder");
            list.files.push_back(entry.path());
        }
    }
}

}  // namespace

bool hasDicomMagic(const std::filesystem::path& file) {
    return hasMagicAt(fileStart(file, 132), 128, "DICM");  // after the 128-byte preamble
}

bool isDicomFolder(const std::filesystem::path& folder) {
    std::error_code error;
    if (std::filesystem::exists(folder / "series.json", error)) return false;
    int budget = 32;
    return findsDicomFile(folder, 2, budget);
}

DicomFileList dicomFilesUnder(const std::filesystem::path& folder) {
    DicomFileList list;
    collect(folder, folder, 0, list);
    std::sort(list.files.begin(), list.files.end());
    return list;
}

}  // namespace tstyles
