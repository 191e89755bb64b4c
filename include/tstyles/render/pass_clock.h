// How long one pass of a frame takes on the device that renders it: a timer query on a GPU; on a
// CPU rasterizer (llvmpipe) glFinish and the wall clock, because llvmpipe's timer queries measure
// when commands are queued and binned, not when its threads rasterize them (a 240-ms raycasting
// pass read 1.6 to 260 ms; docs/performance.md, "Where a frame's time goes").
#pragma once

#include <chrono>
#include <optional>

#include "tstyles/gl/objects.h"

namespace tstyles {

class PassClock {
public:
    // Needs a current OpenGL context.
    explicit PassClock(bool cpuRasterizer);

    void start();
    void stop();
    // Milliseconds between start() and stop(); waits for the GPU.
    double milliseconds() const;

private:
    std::optional<TimerQuery> query_;  // on a GPU
    std::chrono::steady_clock::time_point started_;
    std::chrono::steady_clock::time_point stopped_;
};

}  // namespace tstyles
