// Temporal maximum density change (paper 5.3): the largest difference between the densities of the
// time-steps at the sample, into the gradient TSTF. The sample takes its STF colour and style from
// the time-step with the highest STF opacity; where only one time-step has data the change is
// undefined, and that time-step's STF shows alone.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_GRADIENT_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

struct CompositorState {
    float minimumDensity;
    float maximumDensity;
    Representative representative;
    int withData;  // time-steps with data at the sample: a change needs two
};

CompositorState compositorInit() {
    return CompositorState(1.0, 0.0, noRepresentative(), 0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    state.minimumDensity = min(state.minimumDensity, s.density);
    state.maximumDensity = max(state.maximumDensity, s.density);
    state.withData += 1;
    noteRepresentative(state.representative, s);
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    TimeStepSample representative = representativeSample(state.representative);
    if (!(representative.stf.a > 0.0 && state.withData >= 1)) return transparentCharacteristic();
    if (state.withData < 2) return characteristicOf(READS_STF, 0.0, representative);
    return characteristicOf(READS_GRADIENT_TSTF, state.maximumDensity - state.minimumDensity, representative);
}
