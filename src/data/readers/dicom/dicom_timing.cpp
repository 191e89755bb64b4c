// A tag orders time only when every frame has it: a series where some files lack TriggerTime is
// ordered by the next tag rather than by a mix of present and absent values.
#include "dicom_timing.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tstyles {
namespace {

template <typename Field>
bool everyFrameHas(const std::vector<DicomFrame>& frames, Field field) {
    return !frames.empty() &&
           std::all_of(frames.begin(), frames.end(), [&](const DicomFrame& frame) { return (frame.*field).has_value(); });
}

bool strictlyIncreasing(const std::vector<double>& values) {
    for (std::size_t i = 1; i < values.size(); ++i)
        if (!(values[i] > values[i - 1])) return false;
    return true;
}

std::string stampText(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

// The mean over a step's slices of a tag every frame has.
template <typename Field>
std::vector<double> meanPerStep(const std::vector<std::vector<DicomFrame>>& steps, Field field) {
    std::vector<double> values;
    for (const auto& slices : steps) {
        double sum = 0.0;
        for (const DicomFrame& frame : slices) sum += *(frame.*field);
        values.push_back(sum / double(slices.size()));
    }
    return values;
}

}  // namespace

DicomTimeOrder::DicomTimeOrder(const std::vector<DicomFrame>& frames)
    : byTemporalPosition_(everyFrameHas(frames, &DicomFrame::temporalPosition)),
      byTriggerTime_(everyFrameHas(frames, &DicomFrame::triggerTimeMs)),
      byAcquisition_(everyFrameHas(frames, &DicomFrame::acquiredSeconds)),
      byInstance_(everyFrameHas(frames, &DicomFrame::instanceNumber)) {}

void DicomTimeOrder::sort(std::vector<DicomFrame>& frames) const {
    std::stable_sort(frames.begin(), frames.end(), [this](const DicomFrame& a, const DicomFrame& b) {
        if (byTemporalPosition_ && *a.temporalPosition != *b.temporalPosition)
            return *a.temporalPosition < *b.temporalPosition;
        if (byTriggerTime_ && *a.triggerTimeMs != *b.triggerTimeMs) return *a.triggerTimeMs < *b.triggerTimeMs;
        if (byAcquisition_ && *a.acquiredSeconds != *b.acquiredSeconds) return *a.acquiredSeconds < *b.acquiredSeconds;
        if (byInstance_ && *a.instanceNumber != *b.instanceNumber) return *a.instanceNumber < *b.instanceNumber;
        if (a.file != b.file) return a.file < b.file;
        return a.frameInFile < b.frameInFile;
    });
}

std::optional<std::pair<std::size_t, std::string>> DicomTimeOrder::missingStep(
    const std::vector<DicomFrame>& complete, const std::vector<DicomFrame>& partial) const {
    if (!byTemporalPosition_ && !byTriggerTime_) return std::nullopt;
    const auto key = [this](const DicomFrame& frame) {
        return byTemporalPosition_ ? *frame.temporalPosition : *frame.triggerTimeMs;
    };
    const std::string tag = byTemporalPosition_ ? "TemporalPositionIdentifier " : "TriggerTime ";
    for (std::size_t step = 0; step < complete.size(); ++step) {
        const double wanted = key(complete[step]);
        const bool present = std::any_of(partial.begin(), partial.end(),
                                         [&](const DicomFrame& frame) { return key(frame) == wanted; });
        if (!present) return std::make_pair(step, tag + stampText(wanted));
    }
    return std::nullopt;
}

DicomStepTimes DicomTimeOrder::stepTimes(const std::vector<std::vector<DicomFrame>>& steps) const {
    DicomStepTimes times;
    const std::string ordered = byTemporalPosition_ ? "TemporalPositionIdentifier"
                                : byTriggerTime_   ? "TriggerTime"
                                : byAcquisition_   ? "acquisition time"
                                : byInstance_      ? "InstanceNumber"
                                                   : "file name";
    if (steps.size() == 1) {
        times.values = {0.0};
        times.note = "one time-step (every slice position once)";
        return times;
    }
    if (byTriggerTime_) {
        times.values = meanPerStep(steps, &DicomFrame::triggerTimeMs);
        times.unit = TimeUnit::Milliseconds;
        times.note = std::to_string(steps.size()) + " time-steps ordered by " + ordered + ", times from TriggerTime (ms)";
        if (strictlyIncreasing(times.values)) return times;
    }
    if (byAcquisition_) {
        std::vector<double> earliest;
        for (const auto& slices : steps) {
            double first = *slices.front().acquiredSeconds;
            for (const DicomFrame& frame : slices) first = std::min(first, *frame.acquiredSeconds);
            earliest.push_back(first);
        }
        const double start = *std::min_element(earliest.begin(), earliest.end());
        times.values.clear();
        for (double value : earliest) times.values.push_back(value - start);
        times.unit = TimeUnit::Seconds;
        times.note = std::to_string(steps.size()) + " time-steps ordered by " + ordered +
                     ", times in seconds from the first acquisition (the earliest slice of each)";
        if (strictlyIncreasing(times.values)) return times;
    }
    times.values.clear();
    for (std::size_t step = 0; step < steps.size(); ++step) times.values.push_back(double(step));
    times.unit = TimeUnit::None;
    times.note = std::to_string(steps.size()) + " time-steps ordered by " + ordered +
                 "; no increasing TriggerTime or acquisition time: the time is the step's index";
    return times;
}

}  // namespace tstyles
