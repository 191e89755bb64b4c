// The directory records of a DICOMDIR through GDCM, and their ReferencedFileIDs resolved on disk.
#include "dicom_directory.h"

#include <algorithm>
#include <optional>
#include <set>
#include <string>

#include <gdcmException.h>
#include <gdcmReader.h>

#include "dicom_byte_walk.h"
#include "dicom_elements.h"
#include "dicom_files.h"
#include "dicom_header.h"
#include "tstyles/core/ascii_case.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

const gdcm::Tag kDirectoryRecords(0x0004, 0x1220);
const gdcm::Tag kReferencedFileId(0x0004, 0x1500);

// `name` in `folder`: the exact entry, else the one entry that matches it without regard to case.
std::optional<std::filesystem::path> entryOf(const std::filesystem::path& folder, const std::string& name) {
    std::error_code error;
    if (std::filesystem::exists(folder / name, error)) return folder / name;
    const std::string wanted = asciiLowercase(name);
    std::filesystem::directory_iterator entries(folder, error);
    if (error) return std::nullopt;
    for (const auto& entry : entries)
        if (asciiLowercase(entry.path().filename().string()) == wanted) return entry.path();
    return std::nullopt;
}

// The backslash-separated components of a ReferencedFileID, as a path under `root`.
std::filesystem::path resolveReference(const std::filesystem::path& dicomdir, const std::string& reference,
                                       std::size_t record) {
    const std::string field = "directory record " + std::to_string(record) + " " +
                              dicomTagName(kReferencedFileId, "ReferencedFileID");
    std::filesystem::path found = dicomdir.parent_path().empty() ? "." : dicomdir.parent_path();
    std::size_t start = 0;
    while (start <= reference.size()) {
        const std::size_t end = std::min(reference.find('\\', start), reference.size());
        std::string component = reference.substr(start, end - start);
        while (!component.empty() && component.back() == ' ') component.pop_back();
        if (component.empty() || component == "." || component == ".." || component.find('/') != std::string::npos)
            throwInputError(dicomdir, field,
                            "\"" + reference + "\" is not a path inside the DICOMDIR's folder (components of "
                                               "letters, digits and _ separated by \\)");
        const auto entry = entryOf(found, component);
        if (!entry)
            throwInputError(dicomdir, field,
                            "\"" + reference + "\" names " + (found / component).string() +
                                ", which is not there (a partial copy of the disc?)");
        found = *entry;
        start = end + 1;
    }
    return found;
}

}  // namespace

bool isDicomDirectoryFile(const std::filesystem::path& file) {
    return asciiLowercase(file.filename().string()) == "dicomdir";
}

DicomDirectoryFiles filesOfDicomDirectory(const std::filesystem::path& dicomdir) {
    requireRegularFile(dicomdir, "DICOMDIR");
    silenceGdcm();
    requireWholeDicomFile(dicomdir);
    gdcm::Reader reader;
    reader.SetFileName(dicomdir.c_str());
    if (!reader.Read())
        throwInputError(dicomdir, "", "is not a readable DICOMDIR (GDCM cannot parse it: damaged or truncated?)");
    const gdcm::File& parsed = reader.GetFile();
    const DicomContext context{dicomdir, parsed.GetHeader().GetDataSetTransferSyntax().GetSwapCode() ==
                                             gdcm::SwapCode::BigEndian};
    std::vector<gdcm::DataSet> records;
    try {
        records = dicomItems(parsed.GetDataSet(), kDirectoryRecords, "DirectoryRecordSequence",
                             4 * kMaxDicomFiles, context);
    } catch (const gdcm::Exception& error) {
        throwInputError(dicomdir, "", std::string("is a damaged DICOMDIR (GDCM: ") + error.GetDescription() + ")");
    }
    DicomDirectoryFiles result;
    result.records = records.size();
    std::set<std::filesystem::path> files;
    for (std::size_t index = 0; index < records.size(); ++index) {
        const std::optional<std::string> reference = dicomText(records[index], kReferencedFileId);
        if (!reference) continue;  // patient, study and series records reference no file
        files.insert(resolveReference(dicomdir, *reference, index));
        if (files.size() > kMaxDicomFiles)
            throwInputError(dicomdir, "", "references more than " + std::to_string(kMaxDicomFiles) +
                                              " files: give the series' own folder");
    }
    if (files.empty())
        throwInputError(dicomdir, dicomTagName(kDirectoryRecords, "DirectoryRecordSequence"),
                        "references no file in its " + std::to_string(records.size()) + " records");
    result.files.assign(files.begin(), files.end());
    return result;
}

}  // namespace tstyles
