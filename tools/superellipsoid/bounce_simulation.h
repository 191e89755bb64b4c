// A small deterministic ballistic simulation of the super-ellipsoid: its centre is thrown from the
// left, falls under gravity and bounces on the floor y = 0 while the object spins about z.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "superellipsoid_shape.h"

namespace superellipsoid {

// World units are metres and seconds.
struct BounceParameters {
    // Chosen so that 1.6 s show two bounces and 3.5 m of travel along +x, with the floor contacts
    // at 0.711 s and 1.422 s: exactly time-steps 4 and 8 of the default 10, so they show touching.
    glm::dvec3 launchCentre{0.0, 1.075, 0.0};
    glm::dvec3 launchVelocity{2.2, 2.34, 0.0};
    // Radians per second about +z; negative turns clockwise, so the object tumbles forwards.
    double angularVelocity = -3.0;
    double gravity = 9.81;
    // Applied to the vertical velocity at each floor contact.
    double restitution = 0.75;
    // Fraction of the spin left after each floor contact (friction with the floor).
    double spinKeptPerBounce = 0.8;
    double integrationStep = 0.001;
    double duration = 1.6;
};

struct BodyState {
    double time = 0.0;
    glm::dvec3 centre{0.0};
    double angle = 0.0;  // about +z, radians
};

// One state per integration step, from time 0 to `duration` inclusive.
using Trajectory = std::vector<BodyState>;

Trajectory simulateBounce(const BounceParameters& parameters, const SuperEllipsoidShape& shape);

// The state at `time`, linearly interpolated between the integration steps around it, so samples
// can be uniform in time whatever the integration step.
BodyState sampleTrajectory(const Trajectory& trajectory, double time);

}  // namespace superellipsoid
