// Last time above: the latest time-step whose density at the sample reaches the threshold (a
// departure map), by its STF and the index TSTF. Where no time-step reaches it, nothing shows.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;

uniform float compositorThreshold;

struct CompositorState {
    TimeStepSample last;
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep());
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (s.density < compositorThreshold) return;
    if (s.step > state.last.step) state.last = s;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.last.step < 0 || state.last.stf.a <= 0.0) return transparentCharacteristic();
    return characteristicOf(READS_INDEX_TSTF, float(state.last.step), state.last);
}
