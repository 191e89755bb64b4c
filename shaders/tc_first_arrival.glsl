// First arrival: the earliest time-step whose density at the sample reaches the threshold (an
// arrival map), by its STF and the index TSTF. Where no time-step reaches it, nothing shows.
// With UNCHANGED_TIME, a place whose densities change by no more than unchangedBelow over the
// time-steps shows no time colour (there is no tie: the first or last to reach the threshold is one).
#include "temporal_sample.glsl"

uniform float compositorThreshold;  // the "threshold" option

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

struct CompositorState {
    TimeStepSample first;
    // UNCHANGED_TIME: the densities' range over the time-steps with data, and how many there are.
    float lowest;
    float highest;
    int withData;
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep(), 2.0, -1.0, 0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (UNCHANGED_TIME != 0) {
        state.lowest = min(state.lowest, s.density);
        state.highest = max(state.highest, s.density);
        state.withData += 1;
    }
    if (s.density < compositorThreshold) return;
    if (state.first.step < 0 || s.step < state.first.step) state.first = s;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.first.step < 0 || state.first.stf.a <= 0.0) return transparentCharacteristic();
    // One time-step with data: no change to measure, and nothing to tie with.
    float range = state.withData >= 2 ? state.highest - state.lowest : 2.0;
    return pickedCharacteristic(state.first, range, 2.0);
}
