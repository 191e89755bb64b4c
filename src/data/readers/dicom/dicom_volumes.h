// The frames of one DICOM series stacked into volumes and ordered in time: slices by their position
// along the slice normal (the cross product of the row and column cosines), time-steps at each
// position by TemporalPositionIdentifier, then TriggerTime, then acquisition time, then
// InstanceNumber. Everything a volume needs to be regular is checked here.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "dicom_series.h"
#include "tstyles/data/time_axis.h"

namespace tstyles {

// Slices this far apart along the normal (mm) are at the same position.
inline constexpr double kDicomSamePositionMm = 0.01;
// Direction cosines and pixel spacings (relative) agree when they differ by no more than this.
inline constexpr double kDicomOrientationTolerance = 1e-4;
// Slice gaps within 1 % of the mean gap (or 0.01 mm) are even; others make an uneven z axis.
inline constexpr double kDicomEvenGapTolerance = 0.01;

struct DicomVolumes {
    std::vector<std::vector<DicomFrame>> steps;  // [time-step][slice], slices along +normal
    glm::ivec3 dims{0};                          // columns, rows, slices
    // In DICOM's patient frame (LPS, mm): the first slice's first pixel, and the unit directions
    // of increasing column, row and slice index.
    glm::dvec3 origin{0.0};
    std::array<glm::dvec3, 3> directions{};
    glm::dvec2 pixelSpacing{1.0};       // along x (between columns), along y (between rows)
    std::vector<double> sliceOffsets;   // each slice's distance from the first along the normal
    bool evenSlices = true;
    double sliceSpacing = 1.0;          // the mean gap
    std::vector<double> times;
    TimeUnit timeUnit = TimeUnit::None;
    std::vector<std::string> notes;     // how the slices and times were found
};

// `input` names the folder or file in messages about the series as a whole.
DicomVolumes stackDicomVolumes(const DicomSeriesEntry& series, const std::filesystem::path& input);

}  // namespace tstyles
