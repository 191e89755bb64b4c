// Beam grids in manifests: "dims", the beam angles (an extent or one angle per beam) and "range".
#include "beam_grid_field.h"

#include <cstdint>
#include <sstream>

#include "tstyles/data/beam_geometry.h"

namespace tstyles {
namespace {

// Beams must point into the half-space in front of the transducer; beyond 80 degrees the fan's
// sides approach that plane and tan() grows without bound.
constexpr double kMaxBeamAngleDeg = 80.0;

std::string beamNumberText(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

void checkAngle(const JsonField& field, double angle) {
    if (!(angle > -kMaxBeamAngleDeg && angle < kMaxBeamAngleDeg)) {
        field.fail("beam angle " + beamNumberText(angle) + " deg is outside (-80, 80): beams must point ahead of the "
                   "transducer");
    }
}

// The angles of `count` beams: from "<name>_deg": [first, last] or "<name>_angles_deg": [one per beam].
std::vector<double> readBeamAngles(const JsonField& grid, const std::string& name, int count,
                                   const std::string& dimsPath) {
    const auto extent = grid.optionalMember(name + "_deg");
    const auto list = grid.optionalMember(name + "_angles_deg");
    if (extent && list) list->fail("give either " + name + "_deg or " + name + "_angles_deg, not both");
    if (!extent && !list) {
        grid.fail("missing required key '" + name + "_deg' ([first, last] beam angle in degrees) or '" + name +
                  "_angles_deg' (one angle per beam)");
    }
    std::vector<double> angles;
    if (extent) {
        if (extent->arraySize() != 2) extent->fail("expected [first, last] beam angle in degrees");
        const double first = extent->element(0).finiteNumber();
        const double last = extent->element(1).finiteNumber();
        checkAngle(extent->element(0), first);
        checkAngle(extent->element(1), last);
        if (!(first < last)) {
            extent->fail("the first beam angle must be less than the last, found [" + beamNumberText(first) + ", " +
                         beamNumberText(last) + "]: the fan has no extent");
        }
        return evenBeamAngles(first, last, count);
    }
    if (list->arraySize() != std::size_t(count)) {
        list->fail("expected one angle per beam: " + std::to_string(count) + " (" + dimsPath + "), found " +
                   std::to_string(list->arraySize()));
    }
    for (int index = 0; index < count; ++index) {
        const JsonField element = list->element(std::size_t(index));
        angles.push_back(element.finiteNumber());
        checkAngle(element, angles.back());
        if (index > 0 && !(angles[std::size_t(index)] > angles[std::size_t(index) - 1])) {
            element.fail("beam angles must increase strictly: " + beamNumberText(angles[std::size_t(index)]) +
                         " follows " + beamNumberText(angles[std::size_t(index) - 1]));
        }
    }
    return angles;
}

}  // namespace

BeamGrid readBeamGrid(const JsonField& field) {
    field.allowOnlyKeys({"type", "dims", "azimuth_deg", "azimuth_angles_deg", "elevation_deg",
                         "elevation_angles_deg", "range"});
    BeamGrid grid;
    const JsonField dims = field.member("dims");
    grid.dims = readGridDims(dims, kMaxVoxelsPerStep,
                             {"expected 3 sample counts (beams across, beams along, range samples)",
                              "a beam grid needs two beams each way and two range samples to span a fan",
                              "too many voxels for one time-step"});
    grid.azimuthDeg = readBeamAngles(field, "azimuth", grid.dims.x, dims.path() + "[0]");
    grid.elevationDeg = readBeamAngles(field, "elevation", grid.dims.y, dims.path() + "[1]");

    const JsonField range = field.member("range");
    if (range.arraySize() != 2) range.fail("expected [minimum, maximum] range");
    grid.minRange = range.element(0).finiteNumber();
    grid.maxRange = range.element(1).finiteNumber();
    if (grid.minRange < 0.0) range.element(0).fail("must not be negative, found " + beamNumberText(grid.minRange));
    if (!(grid.minRange < grid.maxRange)) {
        range.fail("the minimum range must be less than the maximum, found [" + beamNumberText(grid.minRange) + ", " +
                   beamNumberText(grid.maxRange) + "]: the fan has no depth");
    }
    return grid;
}

}  // namespace tstyles
