// First arrival: the earliest time-step whose density at the sample reaches the threshold (an
// arrival map), by its STF and the index TSTF. Where no time-step reaches it, nothing shows.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;

uniform float compositorThreshold;

struct CompositorState {
    TimeStepSample first;
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep());
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (s.density < compositorThreshold) return;
    if (state.first.step < 0 || s.step < state.first.step) state.first = s;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.first.step < 0 || state.first.stf.a <= 0.0) return transparentCharacteristic();
    return characteristicOf(READS_INDEX_TSTF, float(state.first.step), state.first);
}
