// Linear trend: the least-squares slope of density over the time-steps' time stamps at the sample
// (density units per unit of the series' time), signed, by the gradient TSTF over its range, which
// for a diverging colour map is centred on 0. Running means and co-moments (Welford) keep it exact
// for stamps far from 0. Colour and style come from the time-step with the highest STF opacity;
// a slope needs two time-steps with data at different times, else the STF shows alone.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_GRADIENT_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

struct CompositorState {
    float meanTime;
    float meanDensity;
    float timeVariance;  // sum of squared time differences from the mean
    float covariance;    // sum of products of time and density differences
    int withData;
    Representative representative;
};

CompositorState compositorInit() {
    return CompositorState(0.0, 0.0, 0.0, 0.0, 0, noRepresentative());
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    float time = timeSteps.steps[s.step].time.x;
    state.withData += 1;
    float weight = 1.0 / float(state.withData);
    float timeDelta = time - state.meanTime;
    state.meanTime += timeDelta * weight;
    state.meanDensity += (s.density - state.meanDensity) * weight;
    state.timeVariance += timeDelta * (time - state.meanTime);
    state.covariance += timeDelta * (s.density - state.meanDensity);
    noteRepresentative(state.representative, s);
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    TimeStepSample representative = representativeSample(state.representative);
    if (state.withData == 0 || representative.stf.a <= 0.0) return transparentCharacteristic();
    if (state.withData < 2 || state.timeVariance <= 0.0) return characteristicOf(READS_STF, 0.0, representative);
    return characteristicOf(READS_GRADIENT_TSTF, state.covariance / state.timeVariance, representative);
}
