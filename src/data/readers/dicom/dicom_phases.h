// Series that are the phases of one study (multi-phase CT: arterial, portal venous, delayed; DCE-MR
// exported one series per phase) read as the time-steps of one series: chosen with --series
// 2,3,4 or all, or found by default when they share a frame of reference, modality, grid and
// acquisition parameters and differ in acquisition time (never a T1 with a T2).
#pragma once

#include <filesystem>
#include <vector>

#include "dicom_series.h"
#include "dicom_volumes.h"

namespace tstyles {

// Without --series: the largest group of phases where it holds more frames than the largest
// series, else the largest series.
DicomSeriesChoice defaultDicomChoice(const std::vector<DicomSeriesEntry>& series, const std::filesystem::path& input);

// The chosen series' volumes as time-steps in acquisition order (the list's order where a series
// has no acquisition time), their times in seconds since the first. Each must be one volume on the
// first's grid (dims, position, orientation, spacing, slice positions); else an InputError on
// --series names the series and what differs. `choice.indices` is put in that order.
DicomVolumes stackDicomPhases(const std::vector<DicomSeriesEntry>& series, DicomSeriesChoice& choice,
                              const std::filesystem::path& input);

}  // namespace tstyles
