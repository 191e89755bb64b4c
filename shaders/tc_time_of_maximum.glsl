// Time of maximum ("time to peak" in perfusion imaging): the time-step with the highest density at
// the sample (the earlier one on a tie), by its STF and the index TSTF. With UNCHANGED_TIME, a place
// that does not change, or whose peak is ahead of every other time-step by no more than a tie (a
// plateau, noise), shows no time colour.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

struct CompositorState {
    TimeStepSample highest;
    // UNCHANGED_TIME: the highest density of the other time-steps (-2 with none), the lowest of all.
    float runnerUp;
    float lowest;
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep(), -2.0, 2.0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    bool higher = state.highest.step < 0 || s.density > state.highest.density ||
                  (s.density == state.highest.density && s.step < state.highest.step);
    if (UNCHANGED_TIME != 0) {
        if (state.highest.step >= 0) state.runnerUp = max(state.runnerUp, higher ? state.highest.density : s.density);
        state.lowest = min(state.lowest, s.density);
    }
    if (higher) state.highest = s;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.highest.step < 0 || state.highest.stf.a <= 0.0) return transparentCharacteristic();
    // One time-step with data (no runner-up): no change to measure, and nothing to tie with.
    float range = state.runnerUp < -1.0 ? 2.0 : state.highest.density - state.lowest;
    return pickedCharacteristic(state.highest, range, state.highest.density - state.runnerUp);
}
