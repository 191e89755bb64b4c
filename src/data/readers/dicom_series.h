// The image series of a set of DICOM files, grouped by SeriesInstanceUID, listed for `info` and
// chosen by --series (its number in the list or its UID) or, by default, the one with most frames.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "dicom_header.h"

namespace tstyles {

struct DicomSeriesEntry {
    std::string uid;
    std::vector<DicomImageFile> files;  // in path order
    std::size_t frameCount() const;
    // "series 2: UID 1.2.3, number 5, "cine", MR, 24 files (24 frames of 16 x 12)".
    std::string describe(std::size_t number) const;
};

// Image files only (files without frames are left out), ordered by SeriesNumber, then UID.
std::vector<DicomSeriesEntry> groupDicomSeries(std::vector<DicomImageFile> files);

struct DicomSeriesChoice {
    std::size_t index = 0;  // into the list
    std::string why;        // "--series 2", "the largest"
};

// `choice` is empty (the largest; the first of equals), a number from 1, or a UID. No match is an
// InputError on --series naming the available series. `input` names the folder or file in messages.
DicomSeriesChoice chooseDicomSeries(const std::vector<DicomSeriesEntry>& series, const std::string& choice,
                                    const std::filesystem::path& input);

}  // namespace tstyles
