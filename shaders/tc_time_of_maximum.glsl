// Time of maximum ("time to peak" in perfusion imaging): the time-step with the highest density at
// the sample (the earlier one on a tie), by its STF and the index TSTF.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;

struct CompositorState {
    TimeStepSample highest;
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep());
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    bool higher = state.highest.step < 0 || s.density > state.highest.density ||
                  (s.density == state.highest.density && s.step < state.highest.step);
    if (higher) state.highest = s;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.highest.step < 0 || state.highest.stf.a <= 0.0) return transparentCharacteristic();
    return characteristicOf(READS_INDEX_TSTF, float(state.highest.step), state.highest);
}
