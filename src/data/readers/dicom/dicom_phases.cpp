// Phases: each series stacked on its own (dicom_volumes.cpp), then the volumes compared and put
// in acquisition order.
#include "dicom_phases.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

// The earliest acquisition moment among the series' frames; empty when any frame lacks one.
std::optional<double> acquiredAt(const DicomSeriesEntry& entry) {
    double earliest = std::numeric_limits<double>::infinity();
    for (const DicomImageFile& file : entry.files)
        for (const DicomFrame& frame : file.frames) {
            if (!frame.acquiredSeconds) return std::nullopt;
            earliest = std::min(earliest, *frame.acquiredSeconds);
        }
    return earliest;
}

// What differs between two volumes' grids, or empty when they are one grid.
std::optional<std::string> gridDifference(const DicomVolumes& a, const DicomVolumes& b) {
    if (a.dims != b.dims) {
        std::ostringstream text;
        text << "is " << b.dims.x << " x " << b.dims.y << " x " << b.dims.z << " voxels, not " << a.dims.x << " x "
             << a.dims.y << " x " << a.dims.z;
        return text.str();
    }
    if (glm::length(a.origin - b.origin) > kDicomSamePositionMm) return "starts elsewhere (ImagePositionPatient)";
    for (std::size_t axis = 0; axis < 3; ++axis)
        if (glm::length(a.directions[axis] - b.directions[axis]) > kDicomOrientationTolerance)
            return "lies in another orientation (ImageOrientationPatient)";
    for (int axis = 0; axis < 2; ++axis)
        if (std::abs(a.pixelSpacing[axis] - b.pixelSpacing[axis]) > kDicomOrientationTolerance * a.pixelSpacing[axis])
            return "has another pixel spacing";
    for (std::size_t slice = 0; slice < a.sliceOffsets.size(); ++slice)
        if (std::abs(a.sliceOffsets[slice] - b.sliceOffsets[slice]) > kDicomSamePositionMm)
            return "has its slices at other positions";
    return std::nullopt;
}

// Whether two series could be phases of one acquisition, by their headers alone.
bool acquiredAlike(const DicomImageFile& a, const DicomImageFile& b) {
    return !a.frameOfReference.empty() && a.frameOfReference == b.frameOfReference && a.modality == b.modality &&
           a.acquisitionParameters == b.acquisitionParameters && a.rows == b.rows && a.columns == b.columns;
}

std::string seriesNumbersText(const std::vector<std::size_t>& indices) {
    std::string text;
    for (std::size_t index : indices) text += (text.empty() ? "" : ",") + std::to_string(index + 1);
    return text;
}

// The one volume of a series that can take part in a group, or empty (a scout without positions,
// a 4D series, a single slice).
std::optional<DicomVolumes> oneVolumeOf(const DicomSeriesEntry& entry, const std::filesystem::path& input) {
    try {
        DicomVolumes volumes = stackDicomVolumes(entry, input);
        if (volumes.steps.size() == 1) return volumes;
    } catch (const InputError&) {
        // Not a volume: not a phase. Chosen alone, the same error reaches the user.
    }
    return std::nullopt;
}

}  // namespace

DicomSeriesChoice defaultDicomChoice(const std::vector<DicomSeriesEntry>& series, const std::filesystem::path& input) {
    const std::size_t largest = largestDicomSeries(series);
    DicomSeriesChoice best{{largest}, series.size() == 1 ? "the only one" : "the largest; --series chooses another"};
    std::size_t bestFrames = series[largest].frameCount();
    std::vector<std::optional<DicomVolumes>> volumes(series.size());
    std::vector<bool> grouped(series.size(), false);
    for (std::size_t i = 0; i < series.size(); ++i) {
        if (grouped[i] || !acquiredAt(series[i])) continue;
        std::vector<std::size_t> group;
        std::vector<double> moments;
        for (std::size_t j = i; j < series.size(); ++j) {
            if (grouped[j] || !acquiredAlike(series[i].files.front(), series[j].files.front())) continue;
            const auto moment = acquiredAt(series[j]);
            if (!moment || std::find(moments.begin(), moments.end(), *moment) != moments.end()) continue;
            if (!volumes[j]) volumes[j] = oneVolumeOf(series[j], input);
            if (!volumes[j]) continue;
            if (!group.empty() && gridDifference(*volumes[group.front()], *volumes[j])) continue;
            group.push_back(j);
            moments.push_back(*moment);
        }
        if (group.size() < 2) continue;
        for (std::size_t member : group) grouped[member] = true;
        std::size_t frames = 0;
        for (std::size_t member : group) frames += series[member].frameCount();
        if (frames > bestFrames) {
            bestFrames = frames;
            best = {group, "phases of one study: the same frame of reference, modality, grid and acquisition "
                           "parameters, acquired at different times; --series " +
                               std::to_string(group.front() + 1) + " takes one"};
        }
    }
    return best;
}

DicomVolumes stackDicomPhases(const std::vector<DicomSeriesEntry>& series, DicomSeriesChoice& choice,
                              const std::filesystem::path& input) {
    struct Phase {
        std::size_t index;
        DicomVolumes volumes;
        std::optional<double> moment;
    };
    std::vector<Phase> phases;
    for (std::size_t index : choice.indices) {
        DicomVolumes volumes = stackDicomVolumes(series[index], input);
        if (volumes.steps.size() != 1)
            throwInputError(input, "--series",
                            "series " + std::to_string(index + 1) + " holds " + std::to_string(volumes.steps.size()) +
                                " time-steps: series read as the time-steps of one must be one volume each");
        if (!phases.empty())
            if (const auto difference = gridDifference(phases.front().volumes, volumes))
                throwInputError(input, "--series",
                                "series " + std::to_string(index + 1) + " " + *difference + " of series " +
                                    std::to_string(phases.front().index + 1) +
                                    ": series read as the time-steps of one must share one grid");
        phases.push_back({index, std::move(volumes), acquiredAt(series[index])});
    }
    const bool timed = std::all_of(phases.begin(), phases.end(), [](const Phase& phase) { return phase.moment; });
    if (timed)
        std::stable_sort(phases.begin(), phases.end(),
                         [](const Phase& a, const Phase& b) { return *a.moment < *b.moment; });
    bool distinct = timed;
    for (std::size_t i = 1; distinct && i < phases.size(); ++i) distinct = *phases[i].moment > *phases[i - 1].moment;

    DicomVolumes stacked = phases.front().volumes;
    stacked.steps.clear();
    stacked.times.clear();
    stacked.notes.erase(std::remove_if(stacked.notes.begin(), stacked.notes.end(),
                                       [](const std::string& note) { return note.find("time-step") != std::string::npos; }),
                        stacked.notes.end());
    std::vector<std::size_t> order;
    for (std::size_t step = 0; step < phases.size(); ++step) {
        stacked.steps.push_back(phases[step].volumes.steps.front());
        stacked.times.push_back(distinct ? *phases[step].moment - *phases.front().moment : double(step));
        order.push_back(phases[step].index);
    }
    choice.indices = order;
    stacked.timeUnit = distinct ? TimeUnit::Seconds : TimeUnit::None;
    stacked.notes.push_back(
        "series " + seriesNumbersText(order) + " read as " + std::to_string(phases.size()) + " time-steps " +
        (distinct ? "in acquisition order, times in seconds from the first acquisition"
                  : "in the list's order, numbered 0, 1, 2, ... (not every series has a distinct acquisition time)"));
    return stacked;
}

}  // namespace tstyles
