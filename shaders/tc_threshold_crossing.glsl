// Threshold crossing: the earliest time-step at which the density at the sample crosses the
// threshold in the option's direction, by the index TSTF. "rising": at or above the threshold where
// the time-step before it (the latest earlier one with data there) was below, the time a front
// reaches a place that was clear before (first-arrival also counts places above the threshold from
// the first time-step on), shown with that time-step's STF; "falling": below it where the
// time-step before was at or above, the time a place clears, shown with the STF of the time-step
// before (the place as it was: below the threshold it would show faint or not at all). Where the
// density never crosses, nothing shows. With UNCHANGED_TIME, a place whose densities change by no
// more than unchangedBelow shows no time colour (there is no tie: the first crossing is one).
#include "temporal_sample.glsl"

uniform float compositorThreshold;  // the "threshold" option
uniform int compositorDirection;    // the "direction" option: 0 rising, 1 falling

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

// The walk meets the time-steps in the order the ray enters their grids, not in time order: each
// waits here, by time-step, marked with the sample's generation (as in tc_chronovolume.glsl), until
// the finish reads them in time order.
TimeStepSample crossingSample[MAX_TIME_STEPS];
int crossingMark[MAX_TIME_STEPS];
int crossingGeneration = 0;

struct CompositorState {
    int earliest;
    int latest;
};

CompositorState compositorInit() {
    crossingGeneration += 1;
    return CompositorState(MAX_TIME_STEPS, -1);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    crossingSample[s.step] = s;
    crossingMark[s.step] = crossingGeneration;
    state.earliest = min(state.earliest, s.step);
    state.latest = max(state.latest, s.step);
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    bool rising = compositorDirection == 0;
    TimeStepSample crossing = noTimeStep();
    TimeStepSample before = noTimeStep();  // the time-step before the crossing
    TimeStepSample previous = noTimeStep();
    bool seen = false;
    bool wasAbove = false;
    float lowest = 2.0;
    float highest = -1.0;
    for (int step = state.earliest; step <= state.latest; ++step) {
        if (crossingMark[step] != crossingGeneration) continue;
        TimeStepSample s = crossingSample[step];
        lowest = min(lowest, s.density);
        highest = max(highest, s.density);
        bool above = s.density >= compositorThreshold;
        if (seen && crossing.step < 0 && above != wasAbove && above == rising) {
            crossing = s;
            before = previous;
        }
        previous = s;
        seen = true;
        wasAbove = above;
    }
    if (crossing.step < 0) return transparentCharacteristic();
    // The side of the crossing at or above the threshold shows the place, at the crossing's time.
    TimeStepSample shown = rising ? crossing : before;
    shown.step = crossing.step;
    if (shown.stf.a <= 0.0) return transparentCharacteristic();
    // A crossing needs two time-steps with data, so the range is theirs.
    return pickedCharacteristic(shown, highest - lowest, 2.0);
}
