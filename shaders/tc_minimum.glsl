// Temporal minimum: the time-step with the lowest density at the sample (the earlier one on a
// tie), by its STF and the index TSTF. A place shows only where every time-step there is dense
// enough for the STF: what persists through the whole series. With UNCHANGED_TIME, a minimum below
// every other time-step by no more than unchangedBelow (a tie, noise) shows no time colour.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;

struct CompositorState {
    TimeStepSample lowest;
    float runnerUp;  // UNCHANGED_TIME: the lowest density of the other time-steps (3 with none)
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep(), 3.0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    bool lower = state.lowest.step < 0 || s.density < state.lowest.density ||
                 (s.density == state.lowest.density && s.step < state.lowest.step);
    if (UNCHANGED_TIME != 0 && state.lowest.step >= 0)
        state.runnerUp = min(state.runnerUp, lower ? state.lowest.density : s.density);
    if (lower) state.lowest = s;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.lowest.step < 0 || state.lowest.stf.a <= 0.0) return transparentCharacteristic();
    if (!timeDecides(state.runnerUp - state.lowest.density)) return unchangedCharacteristic(state.lowest);
    return characteristicOf(READS_INDEX_TSTF, float(state.lowest.step), state.lowest);
}
