// Smoothed frame rate and measured intervals.
#include "frame_statistics.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace tstyles::viewer {

void FrameStatistics::addFrame(double seconds, bool drewPreview, bool refined) {
    if (seconds > 0.0) {
        const double fps = 1.0 / seconds;
        smoothedFps_ = smoothedFps_ == 0.0 ? fps : 0.9 * smoothedFps_ + 0.1 * fps;
    }
    if (!measuring_) return;
    frameMs_.push_back(seconds * 1000.0);
    previews_ += drewPreview ? 1 : 0;
    tiles_ += refined ? 1 : 0;
}

void FrameStatistics::start(const std::string& label) {
    measuring_ = true;
    label_ = label;
    frameMs_.clear();
    previews_ = 0;
    tiles_ = 0;
}

FrameMeasurement FrameStatistics::stop() {
    FrameMeasurement measurement;
    measurement.label = label_;
    measurement.frames = int(frameMs_.size());
    measurement.seconds = std::accumulate(frameMs_.begin(), frameMs_.end(), 0.0) / 1000.0;
    if (!frameMs_.empty()) {
        measurement.framesPerSecond = double(frameMs_.size()) / measurement.seconds;
        std::vector<double> sorted = frameMs_;
        std::sort(sorted.begin(), sorted.end());
        measurement.medianMs = sorted[sorted.size() / 2];
        measurement.worstMs = sorted.back();
    }
    measurement.previews = previews_;
    measurement.tiles = tiles_;
    measuring_ = false;
    return measurement;
}

std::string FrameStatistics::describe(const FrameMeasurement& m) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "measure %s: %d frames in %.2f s = %.1f fps (median frame %.1f ms, worst %.1f ms; "
                  "%d previews, %d refining frames)",
                  m.label.c_str(), m.frames, m.seconds, m.framesPerSecond, m.medianMs, m.worstMs, m.previews, m.tiles);
    return text;
}

}  // namespace tstyles::viewer
