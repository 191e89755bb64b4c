// Temporal standard deviation: the population standard deviation of the densities of the
// time-steps with data at the sample (Welford's running mean and sum of squares, which do not lose
// the small spread of large values), by the gradient TSTF over its range. Colour and style come
// from the time-step with the highest STF opacity; with data in one time-step only, its STF shows.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_GRADIENT_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

struct CompositorState {
    float mean;
    float sumOfSquares;  // of the differences from the mean
    int withData;
    Representative representative;
};

CompositorState compositorInit() {
    return CompositorState(0.0, 0.0, 0, noRepresentative());
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    state.withData += 1;
    float delta = s.density - state.mean;
    state.mean += delta / float(state.withData);
    state.sumOfSquares += delta * (s.density - state.mean);
    noteRepresentative(state.representative, s);
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    TimeStepSample representative = representativeSample(state.representative);
    if (state.withData == 0 || representative.stf.a <= 0.0) return transparentCharacteristic();
    if (state.withData < 2) return characteristicOf(READS_STF, 0.0, representative);
    float deviation = sqrt(max(state.sumOfSquares, 0.0) / float(state.withData));
    return characteristicOf(READS_GRADIENT_TSTF, deviation, representative);
}
