// The vessel's course and attitude (see vessel_track.h).
#include "vessel_track.h"

#include <cmath>
#include <numbers>

#include <glm/gtc/quaternion.hpp>

namespace sonar {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

glm::dquat turnAbout(const glm::dvec3& axis, double angleRad) {
    return glm::dquat(std::cos(0.5 * angleRad), std::sin(0.5 * angleRad) * axis);
}

// Grid-local axes to the vessel's frame (x forward, y up, z starboard): local x -> +z,
// local y -> -x, local z -> -y. The columns are orthonormal with determinant +1.
glm::dquat mountingRotation() {
    const glm::dmat3 columns(glm::dvec3(0.0, 0.0, 1.0), glm::dvec3(-1.0, 0.0, 0.0),
                             glm::dvec3(0.0, -1.0, 0.0));
    return glm::normalize(glm::quat_cast(columns));
}

}  // namespace

double pingTime(const VesselTrack& track, int ping) { return track.pingInterval * double(ping); }

tstyles::Placement transducerPose(const VesselTrack& track, double time) {
    const double sway = kTwoPi / track.swayPeriod;
    const glm::dvec3 position(track.speed * time, -track.transducerDepth,
                              track.swayAmplitude * std::sin(sway * time));
    // Heading follows the course: the velocity is (speed, 0, swayAmplitude * sway * cos).
    // A turn about +y by a takes +x to (cos a, 0, -sin a), hence the minus sign.
    const double heading = -std::atan2(track.swayAmplitude * sway * std::cos(sway * time), track.speed);
    const double roll = glm::radians(track.rollAmplitudeDeg) * std::sin(kTwoPi * time / track.rollPeriod);
    const double pitch = glm::radians(track.pitchAmplitudeDeg) * std::sin(kTwoPi * time / track.pitchPeriod);
    const glm::dquat attitude = turnAbout({0.0, 1.0, 0.0}, heading) * turnAbout({0.0, 0.0, 1.0}, pitch) *
                                turnAbout({1.0, 0.0, 0.0}, roll);
    tstyles::Placement pose;
    pose.origin = position;
    pose.rotation = glm::normalize(attitude * mountingRotation());
    return pose;
}

}  // namespace sonar
