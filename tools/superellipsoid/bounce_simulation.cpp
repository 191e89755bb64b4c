// Semi-implicit Euler integration of the thrown, bouncing, spinning super-ellipsoid.
#include "bounce_simulation.h"

#include <algorithm>
#include <cmath>

namespace superellipsoid {

Trajectory simulateBounce(const BounceParameters& parameters, const SuperEllipsoidShape& shape) {
    const double dt = parameters.integrationStep;
    const auto stepCount = static_cast<long>(std::lround(parameters.duration / dt));

    glm::dvec3 centre = parameters.launchCentre;
    glm::dvec3 velocity = parameters.launchVelocity;
    double angle = 0.0;
    double angularVelocity = parameters.angularVelocity;

    Trajectory trajectory;
    trajectory.reserve(static_cast<std::size_t>(stepCount) + 1);
    trajectory.push_back({0.0, centre, angle});
    for (long step = 1; step <= stepCount; ++step) {
        // Semi-implicit Euler: velocity first, then position with the new velocity.
        velocity.y -= parameters.gravity * dt;
        centre += velocity * dt;
        angle += angularVelocity * dt;

        // The lowest point of the turned object, not its centre, meets the floor. Turning can
        // also push the lowest point into the floor while rising; the object is lifted out then.
        const double depth = shape.depthBelowCentre(angle);
        if (centre.y < depth) {
            centre.y = depth;
            if (velocity.y < 0.0) {
                velocity.y = -parameters.restitution * velocity.y;
                angularVelocity *= parameters.spinKeptPerBounce;
            }
        }
        // Time from the step count rather than a running sum, so no rounding drift.
        trajectory.push_back({static_cast<double>(step) * dt, centre, angle});
    }
    return trajectory;
}

BodyState sampleTrajectory(const Trajectory& trajectory, double time) {
    const double dt = trajectory.size() > 1 ? trajectory[1].time - trajectory[0].time : 1.0;
    const double position = std::clamp(time / dt, 0.0, static_cast<double>(trajectory.size() - 1));
    const auto before = std::min(static_cast<std::size_t>(position), trajectory.size() - 1);
    const auto after = std::min(before + 1, trajectory.size() - 1);
    const double weight = position - static_cast<double>(before);

    const BodyState& a = trajectory[before];
    const BodyState& b = trajectory[after];
    return {time, glm::mix(a.centre, b.centre, weight), glm::mix(a.angle, b.angle, weight)};
}

}  // namespace superellipsoid
