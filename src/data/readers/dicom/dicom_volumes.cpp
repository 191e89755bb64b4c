// Stacking slices: one position per slice of the volume, the same positions in every time-step
// (else an error says which time-step lacks which slice), and slices that lie on the normal through
// the first one (a tilted gantry's sheared stack is refused rather than shown straight).
#include "dicom_volumes.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "dicom_timing.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

std::string positionText(double value) {
    std::ostringstream text;
    text << std::round(value * 1000.0) / 1000.0 << " mm";
    return text.str();
}

// A frame without the tags that place it cannot be part of a volume.
void requirePlaced(const DicomFrame& frame) {
    const auto missing = [&](const char* tag) {
        throwInputError(frame.file, tag, "is missing (frame " + std::to_string(frame.frameInFile + 1) +
                                             "): the slices of a volume need it");
    };
    if (!frame.position) missing("(0020,0032) ImagePositionPatient");
    if (!frame.orientation) missing("(0020,0037) ImageOrientationPatient");
    if (!frame.pixelSpacing) missing("(0028,0030) PixelSpacing");
    if (!((*frame.pixelSpacing)[0] > 0.0) || !((*frame.pixelSpacing)[1] > 0.0))
        throwInputError(frame.file, "(0028,0030) PixelSpacing", "must be positive");
}

// Every frame like the first: same size, orientation and pixel spacing.
void requireAlike(const DicomSeriesEntry& series, const DicomFrame& first) {
    const DicomImageFile& model = series.files.front();
    for (const DicomImageFile& file : series.files) {
        if (file.rows != model.rows || file.columns != model.columns)
            throwInputError(file.file, "(0028,0010) Rows",
                            "the image is " + std::to_string(file.columns) + " x " + std::to_string(file.rows) + ", " +
                                model.file.filename().string() + " of the same series is " +
                                std::to_string(model.columns) + " x " + std::to_string(model.rows));
        for (const DicomFrame& frame : file.frames) {
            requirePlaced(frame);
            for (std::size_t i = 0; i < 6; ++i)
                if (std::abs((*frame.orientation)[i] - (*first.orientation)[i]) > kDicomOrientationTolerance)
                    throwInputError(frame.file, "(0020,0037) ImageOrientationPatient",
                                    "differs from " + first.file.filename().string() +
                                        "'s: a series' slices must share one orientation (tolerance 1e-4)");
            for (std::size_t i = 0; i < 2; ++i)
                if (std::abs((*frame.pixelSpacing)[i] - (*first.pixelSpacing)[i]) >
                    kDicomOrientationTolerance * (*first.pixelSpacing)[i])
                    throwInputError(frame.file, "(0028,0030) PixelSpacing",
                                    "differs from " + first.file.filename().string() +
                                        "'s: a series' slices must share one pixel spacing (relative tolerance 1e-4)");
        }
    }
}

std::array<glm::dvec3, 3> directionsOf(const DicomFrame& first) {
    const auto& c = *first.orientation;
    const glm::dvec3 row(c[0], c[1], c[2]), column(c[3], c[4], c[5]);
    if (std::abs(glm::length(row) - 1.0) > 1e-3 || std::abs(glm::length(column) - 1.0) > 1e-3 ||
        std::abs(glm::dot(row, column)) > 1e-3)
        throwInputError(first.file, "(0020,0037) ImageOrientationPatient",
                        "the row and column cosines must be two orthogonal unit vectors");
    const glm::dvec3 x = glm::normalize(row), y = glm::normalize(column);
    return {x, y, glm::normalize(glm::cross(x, y))};
}

struct SlicePosition {
    double along = 0.0;               // on the normal
    std::vector<DicomFrame> frames;   // the time-steps' slices here, in time order
};

std::vector<SlicePosition> groupByPosition(std::vector<DicomFrame> frames, const glm::dvec3& normal,
                                           const DicomTimeOrder& order) {
    const auto along = [&](const DicomFrame& frame) { return glm::dot(*frame.position, normal); };
    std::stable_sort(frames.begin(), frames.end(), [&](const DicomFrame& a, const DicomFrame& b) {
        return along(a) < along(b);
    });
    std::vector<SlicePosition> positions;
    for (DicomFrame& frame : frames) {
        if (positions.empty() || along(frame) - positions.back().along > kDicomSamePositionMm)
            positions.push_back({along(frame), {}});
        positions.back().frames.push_back(std::move(frame));
    }
    for (SlicePosition& position : positions) order.sort(position.frames);
    return positions;
}

// Every slice on the normal through the first: a sheared stack (tilted gantry) is not a volume.
void requireStackedOnNormal(const std::vector<SlicePosition>& positions, const glm::dvec3& normal, double pixel) {
    const glm::dvec3 start = *positions.front().frames.front().position;
    const double tolerance = std::max(kDicomSamePositionMm, 0.01 * pixel);
    for (const SlicePosition& position : positions)
        for (const DicomFrame& frame : position.frames) {
            const glm::dvec3 offset = *frame.position - start;
            const double aside = glm::length(offset - glm::dot(offset, normal) * normal);
            if (aside > tolerance)
                throwInputError(frame.file, "(0020,0032) ImagePositionPatient",
                                "lies " + positionText(aside) +
                                    " off the slice normal through the first slice: sheared stacks (gantry tilt) "
                                    "are not supported");
        }
}

void requireEveryStepEverywhere(const std::vector<SlicePosition>& positions, const DicomTimeOrder& order,
                                const std::filesystem::path& input) {
    const SlicePosition& full = *std::max_element(positions.begin(), positions.end(), [](const auto& a, const auto& b) {
        return a.frames.size() < b.frames.size();
    });
    const std::size_t steps = full.frames.size();
    for (const SlicePosition& position : positions) {
        if (position.frames.size() == steps) continue;
        const std::string where = "the slice at position " + positionText(position.along) + " along the normal";
        const auto missing = order.missingStep(full.frames, position.frames);
        if (missing)
            throwInputError(input, "", "time-step " + std::to_string(missing->first) + " (" + missing->second +
                                           ") lacks " + where + " (" + std::to_string(position.frames.size()) +
                                           " of " + std::to_string(steps) + " time-steps have it)");
        throwInputError(input, "", where + " is in " + std::to_string(position.frames.size()) + " of the " +
                                       std::to_string(steps) + " time-steps: a time-step lacks it");
    }
}

void placeSlices(const std::vector<SlicePosition>& positions, DicomVolumes& volumes) {
    for (const SlicePosition& position : positions) volumes.sliceOffsets.push_back(position.along - positions.front().along);
    const std::size_t count = positions.size();
    volumes.sliceSpacing = volumes.sliceOffsets.back() / double(count - 1);
    const double tolerance = std::max(kDicomSamePositionMm, kDicomEvenGapTolerance * volumes.sliceSpacing);
    for (std::size_t i = 1; i < count; ++i)
        if (std::abs(volumes.sliceOffsets[i] - volumes.sliceOffsets[i - 1] - volumes.sliceSpacing) > tolerance)
            volumes.evenSlices = false;
    volumes.notes.push_back(std::to_string(count) + " slices " +
                            (volumes.evenSlices ? positionText(volumes.sliceSpacing) + " apart"
                                                : "unevenly spaced (z positions kept as they are)") +
                            ", ordered by ImagePositionPatient along the slice normal");
}

}  // namespace

DicomVolumes stackDicomVolumes(const DicomSeriesEntry& series, const std::filesystem::path& input) {
    const DicomFrame& first = series.files.front().frames.front();
    requirePlaced(first);
    requireAlike(series, first);
    DicomVolumes volumes;
    volumes.directions = directionsOf(first);
    volumes.pixelSpacing = {(*first.pixelSpacing)[1], (*first.pixelSpacing)[0]};

    std::vector<DicomFrame> frames;
    for (const DicomImageFile& file : series.files) frames.insert(frames.end(), file.frames.begin(), file.frames.end());
    const DicomTimeOrder order(frames);
    const std::vector<SlicePosition> positions = groupByPosition(std::move(frames), volumes.directions[2], order);
    if (positions.size() < 2)
        throwInputError(input, "(0020,0032) ImagePositionPatient",
                        "all " + std::to_string(series.frameCount()) +
                            " frames of the series lie at one position: a volume needs at least 2 slices");
    requireStackedOnNormal(positions, volumes.directions[2], std::min(volumes.pixelSpacing.x, volumes.pixelSpacing.y));
    requireEveryStepEverywhere(positions, order, input);

    const std::size_t stepCount = positions.front().frames.size();
    volumes.steps.assign(stepCount, {});
    for (const SlicePosition& position : positions)
        for (std::size_t step = 0; step < stepCount; ++step) volumes.steps[step].push_back(position.frames[step]);
    volumes.dims = {int(series.files.front().columns), int(series.files.front().rows), int(positions.size())};
    volumes.origin = *positions.front().frames.front().position;
    placeSlices(positions, volumes);
    const DicomStepTimes times = order.stepTimes(volumes.steps);
    volumes.times = times.values;
    volumes.timeUnit = times.unit;
    volumes.notes.push_back(times.note);
    return volumes;
}

}  // namespace tstyles
