// Temporal minimum: the time-step with the lowest density at the sample (the earlier one on a
// tie), by its STF and the index TSTF. A place shows only where every time-step there is dense
// enough for the STF: what persists through the whole series.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;

struct CompositorState {
    TimeStepSample lowest;
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep());
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    bool lower = state.lowest.step < 0 || s.density < state.lowest.density ||
                 (s.density == state.lowest.density && s.step < state.lowest.step);
    if (lower) state.lowest = s;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.lowest.step < 0 || state.lowest.stf.a <= 0.0) return transparentCharacteristic();
    return characteristicOf(READS_INDEX_TSTF, float(state.lowest.step), state.lowest);
}
