// Reading a time-step's density at a world position on the CPU, the way the raycaster reads its
// volume texture: trilinear between the grid's samples. For picking and probes, not for rendering.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"

namespace tstyles {

// The time-step's density at `world`, or none when the position lies outside its grid (a
// tolerance of a thousandth of a voxel lets points on the boundary count as inside). Inside the
// grid but where it has no data (missing values, as the renderer decides: the corners with data
// weigh less than half) the result is missingDensity(); test it with isMissing.
std::optional<double> sampleDensity(const TimeStep& step, const glm::dvec3& world);

class StructuredPointLocator;

// Temporal profiles of one series at many points: a structured grid's point locator (a search
// structure over all its cells) is made once per distinct grid, not once per point.
class TemporalProfiler {
public:
    explicit TemporalProfiler(const Series& series);  // keeps a reference: `series` must outlive it
    ~TemporalProfiler();
    TemporalProfiler(const TemporalProfiler&) = delete;
    TemporalProfiler& operator=(const TemporalProfiler&) = delete;

    // The density of every time-step at `world`.
    std::vector<std::optional<double>> profile(const glm::dvec3& world) const;

private:
    const Series& series_;
    // Per time-step, the locator of its structured grid (shared by the time-steps of one grid).
    std::vector<const StructuredPointLocator*> locatorOfStep_;
    std::vector<std::unique_ptr<StructuredPointLocator>> locators_;
};

// The density of every time-step at `world`: the temporal profile of that point (for one point;
// TemporalProfiler for many).
std::vector<std::optional<double>> temporalProfile(const Series& series, const glm::dvec3& world);

}  // namespace tstyles
