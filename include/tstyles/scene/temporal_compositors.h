// The table of temporal compositors: one line each, naming its scene-file name, its shader module
// (shaders/tc_*.glsl), the transfer function that reads it and the options it takes. Adding a
// compositor is a new module and a line here (and a value of TemporalCompositor).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "tstyles/scene/scene.h"

namespace tstyles {

// How an automatic ("auto") gradient TSTF range fits a compositor's characteristic, from the
// series' typical largest change over time C (typicalLargestChange) and its time span T.
enum class AutomaticRange {
    Change,          // [0, C]
    HalfChange,      // [0, C / 2]: a standard deviation of values spread over C is at most C / 2
    SignedChange,    // [-C, C]
    SignedPerTime,   // [-C / T, C / T]: the slope of a change of C over the whole series
};

struct TemporalCompositorInfo {
    TemporalCompositor compositor;
    const char* name;          // in scene files, --tc and the viewer
    const char* shaderModule;  // in shaders/; empty for the scene's own (CustomCompositor)
    CompositorReads reads;
    AutomaticRange range;      // GradientTstf only
    bool takesThreshold;
    bool takesSteps;
    bool takesUnchanged;  // picks a time-step: CompositorOptions::unchanged applies
    const char* summary;       // one line for help texts and the viewer
};

std::span<const TemporalCompositorInfo> temporalCompositors();
const TemporalCompositorInfo& compositorInfo(TemporalCompositor compositor);
// What reads the scene's compositor: the table's entry, or the custom compositor's own choice.
CompositorReads compositorReads(const Scene& scene);

}  // namespace tstyles
