// Temporal minimum: the time-step with the lowest density at the sample (the earlier one on a
// tie), by its STF and the index TSTF. A place shows only where every time-step there is dense
// enough for the STF: what persists through the whole series. With UNCHANGED_TIME, a place that does
// not change, or whose minimum is below every other time-step's by no more than a tie, shows no time
// colour.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

struct CompositorState {
    TimeStepSample lowest;
    // UNCHANGED_TIME: the lowest density of the other time-steps (3 with none), the highest of all.
    float runnerUp;
    float highest;
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep(), 3.0, -1.0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    bool lower = state.lowest.step < 0 || s.density < state.lowest.density ||
                 (s.density == state.lowest.density && s.step < state.lowest.step);
    if (UNCHANGED_TIME != 0) {
        if (state.lowest.step >= 0) state.runnerUp = min(state.runnerUp, lower ? state.lowest.density : s.density);
        state.highest = max(state.highest, s.density);
    }
    if (lower) state.lowest = s;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.lowest.step < 0 || state.lowest.stf.a <= 0.0) return transparentCharacteristic();
    // One time-step with data (no runner-up): no change to measure, and nothing to tie with.
    float range = state.runnerUp > 2.0 ? 2.0 : state.highest - state.lowest.density;
    return pickedCharacteristic(state.lowest, range, state.runnerUp - state.lowest.density);
}
