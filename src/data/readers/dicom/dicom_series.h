// The image series of a set of DICOM files, grouped by SeriesInstanceUID, listed for `info` and
// chosen by --series (numbers in the list, a UID, or all).
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
    std::vector<std::size_t> indices;  // into the list; several: phases read as time-steps (dicom_phases.h)
    std::string why;                   // "--series 2", "the largest"
    bool taken(std::size_t index) const;
};

// `choice` is a number from 1, a UID, "all" (every series), or numbers separated by commas
// ("2,3,4"): the series in the list that it names. Empty: nothing chosen (`indices` empty; the
// default is dicom_phases.h's). No match, a number twice, or a number out of the list is an
// InputError on --series naming the available series. `input` names the folder or file in messages.
DicomSeriesChoice chooseDicomSeries(const std::vector<DicomSeriesEntry>& series, const std::string& choice,
                                    const std::filesystem::path& input);

// The series with the most frames (the first of equals).
std::size_t largestDicomSeries(const std::vector<DicomSeriesEntry>& series);

}  // namespace tstyles
