// The time slider and play button of the dataset panel: which time-step is shown alone (the
// renderer's solo mode, for comparing with plain playback) and the playback clock.
#pragma once

#include <optional>

namespace tstyles::viewer {

struct TimeControl {
    int step = 0;
    bool solo = false;  // show `step` alone instead of the temporal composite
    bool playing = false;
    float stepsPerSecond = 2.0f;
    double sinceLastStep = 0.0;

    std::optional<int> soloTimeStep() const { return solo ? std::optional<int>(step) : std::nullopt; }

    // Playback: moves to the next time-step (looping) whenever its time has come.
    void advance(double seconds, int stepCount) {
        if (step >= stepCount) step = stepCount > 0 ? stepCount - 1 : 0;
        if (!playing || stepCount <= 0) return;
        sinceLastStep += seconds;
        if (sinceLastStep * stepsPerSecond < 1.0) return;
        sinceLastStep = 0.0;
        step = (step + 1) % stepCount;
    }

    void togglePlay() {
        playing = !playing;
        if (playing) solo = true;  // playback shows one time-step after the other
        sinceLastStep = 0.0;
    }
};

}  // namespace tstyles::viewer
