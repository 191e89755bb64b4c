// Assembles the sonar series ping by ping (see sonar_series.h).
#include "sonar_series.h"

#include "fish_school.h"
#include "ping_echoes.h"
#include "sonar_random.h"
#include "tstyles/data/beam_geometry.h"
#include "vessel_track.h"

namespace sonar {
namespace {

// What each seed drawn from the base seed is for.
constexpr std::uint32_t kSchoolPurpose = 1;
constexpr std::uint32_t kWanderPurpose = 2;
constexpr std::uint32_t kSpecklePurpose = 3;

std::vector<std::uint8_t> littleEndianBytes(const std::vector<std::uint16_t>& values) {
    std::vector<std::uint8_t> bytes;
    bytes.reserve(2 * values.size());
    for (std::uint16_t value : values) {
        bytes.push_back(std::uint8_t(value & 0xFFu));
        bytes.push_back(std::uint8_t(value >> 8));
    }
    return bytes;
}

}  // namespace

tstyles::BeamGrid surveyBeamGrid(const glm::ivec3& dims) {
    tstyles::BeamGrid grid;
    grid.dims = dims;
    grid.azimuthDeg = tstyles::evenBeamAngles(-30.0, 30.0, dims.x);
    grid.elevationDeg = tstyles::evenBeamAngles(-20.0, 20.0, dims.y);
    grid.minRange = 2.0;
    grid.maxRange = 120.0;
    return grid;
}

tstyles::RawSeries buildSonarSeries(const SonarSeriesOptions& options) {
    const VesselTrack track;
    const tstyles::BeamGrid grid = surveyBeamGrid(options.dims);
    const std::vector<Fish> school = drawSchool(options.fishCount, pingSeed(options.seed, 0, kSchoolPurpose));

    tstyles::RawSeries series;
    series.name = "synthetic sonar survey (fish school over the seabed)";
    series.valueRange = {0.0, 65535.0};
    for (int ping = 0; ping < options.pings; ++ping) {
        const double time = pingTime(track, ping);
        const tstyles::Placement pose = transducerPose(track, time);
        const SchoolShape shape = schoolShapeAt(time);
        const auto fishWorld = fishPositions(school, shape, pingSeed(options.seed, ping, kWanderPurpose));
        PingEchoes echoes =
            synthesizePing(grid, pose, shape, school, fishWorld, pingSeed(options.seed, ping, kSpecklePurpose));

        tstyles::RawTimeStep step;
        step.time = time;
        step.beamGrid = grid;
        step.placement = pose;
        step.type = tstyles::ValueType::UInt16;
        step.bytes = littleEndianBytes(echoes.values);
        step.mask = std::move(echoes.mask);
        series.steps.push_back(std::move(step));
    }
    return series;
}

}  // namespace sonar
