// The survey vessel: where its downward-looking multibeam transducer is at each ping, and how it is
// turned. World y is up, the sea surface is y = 0, the vessel steams along +x on a gently curving
// track and rolls and pitches a little, so consecutive fans overlap only partly.
#pragma once

#include "tstyles/data/series.h"

namespace sonar {

struct VesselTrack {
    double pingInterval = 2.0;     // seconds between pings
    double speed = 3.0;            // metres per second along the track (6 m between pings)
    double transducerDepth = 3.0;  // metres below the surface
    double swayAmplitude = 3.0;    // metres across the track (z) of the curving course
    double swayPeriod = 56.0;      // seconds
    double rollAmplitudeDeg = 3.0;
    double rollPeriod = 7.0;       // seconds
    double pitchAmplitudeDeg = 1.5;
    double pitchPeriod = 5.3;      // seconds
};

// The time of a ping in seconds.
double pingTime(const VesselTrack& track, int ping);

// The transducer's pose at time t: grid-local +z (the beams' axis) points down, grid-local x
// (azimuth, across the track) along world +z and grid-local y (elevation, along the track)
// along world -x, before heading, roll and pitch turn it.
tstyles::Placement transducerPose(const VesselTrack& track, double time);

}  // namespace sonar
