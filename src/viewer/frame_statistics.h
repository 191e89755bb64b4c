// Frame-rate bookkeeping: a smoothed rate for the overlay, and measurements between a script's
// measure-start and measure-stop (how the FPS figures in docs/viewer.md were taken).
#pragma once

#include <string>
#include <vector>

namespace tstyles::viewer {

struct FrameMeasurement {
    std::string label;
    int frames = 0;
    double seconds = 0.0;
    double framesPerSecond = 0.0;
    double medianMs = 0.0;
    double worstMs = 0.0;
    int previews = 0;  // frames that drew a new preview
    int tiles = 0;     // frames that refined
};

class FrameStatistics {
public:
    // One finished frame: how long its work took (input, UI, rendering, swap; not the sleep of an
    // idle viewer waiting for input) and what the volume did in it.
    void addFrame(double seconds, bool drewPreview, bool refined);
    double framesPerSecond() const { return smoothedFps_; }

    void start(const std::string& label);
    // Ends the measurement (none running: an empty one) and returns it.
    FrameMeasurement stop();
    static std::string describe(const FrameMeasurement& measurement);

private:
    double smoothedFps_ = 0.0;
    bool measuring_ = false;
    std::string label_;
    std::vector<double> frameMs_;
    int previews_ = 0;
    int tiles_ = 0;
};

}  // namespace tstyles::viewer
