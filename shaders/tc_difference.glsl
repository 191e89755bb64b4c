// Difference of two chosen time-steps: density(to) - density(from) at the sample, signed, by the
// gradient TSTF over its range (centred on 0 for a diverging colour map). Where either time-step
// has no data, nothing shows. Colour and style come from the more opaque of the two.
#include "temporal_sample.glsl"

uniform ivec2 compositorSteps;  // the "steps" option: [from, to]

const int COMPOSITOR_READS = READS_GRADIENT_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

struct CompositorState {
    TimeStepSample from;
    TimeStepSample to;
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep(), noTimeStep());
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (s.step == compositorSteps.x) state.from = s;
    if (s.step == compositorSteps.y) state.to = s;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.from.step < 0 || state.to.step < 0) return transparentCharacteristic();
    TimeStepSample representative = state.to.stf.a >= state.from.stf.a ? state.to : state.from;
    if (representative.stf.a <= 0.0) return transparentCharacteristic();
    representative.inMask = state.from.inMask || state.to.inMask;
    return characteristicOf(READS_GRADIENT_TSTF, state.to.density - state.from.density, representative);
}
