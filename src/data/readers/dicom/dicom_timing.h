// Time in a DICOM series: which tags order the time-steps at one slice position
// (TemporalPositionIdentifier, TriggerTime, acquisition time, InstanceNumber: each used when every
// frame has it), and the time stamps of the ordered steps with their unit.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dicom_header.h"
#include "tstyles/data/time_axis.h"

namespace tstyles {

struct DicomStepTimes {
    std::vector<double> values;
    TimeUnit unit = TimeUnit::None;
    std::string note;  // where the times came from
};

class DicomTimeOrder {
public:
    // Looks at which time tags every frame of the series has.
    explicit DicomTimeOrder(const std::vector<DicomFrame>& frames);

    // Earliest first, by the tags every frame has, then by file name and frame number.
    void sort(std::vector<DicomFrame>& frames) const;

    // Which time-step of `complete` (one position's frames, in order) `partial` lacks, with its
    // tag ("TemporalPositionIdentifier 3"); empty when no per-volume tag tells.
    std::optional<std::pair<std::size_t, std::string>> missingStep(const std::vector<DicomFrame>& complete,
                                                                   const std::vector<DicomFrame>& partial) const;

    // The stamps of the time-steps ([step][slice]): TriggerTime in ms, else seconds since the first
    // acquisition, else the step's index. Stamps that do not increase fall back to the next source.
    DicomStepTimes stepTimes(const std::vector<std::vector<DicomFrame>>& steps) const;

private:
    bool byTemporalPosition_ = false;
    bool byTriggerTime_ = false;
    bool byAcquisition_ = false;
    bool byInstance_ = false;
};

}  // namespace tstyles
