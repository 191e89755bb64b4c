// The scene's own compositor (CustomCompositor; docs/compositors.md): its code is the body of
// customCompositor() below, over the time-steps at the sample in time order. Its inputs are
// read-only, its loops run over `count` (the scene reader checks both, and that it reaches nothing
// of the program but its inputs and GLSL's built-in math). It returns a time-step index (read by
// the index TSTF; outside the series or without data there: transparent) or a value for the
// gradient TSTF, as the scene's "reads" says (CUSTOM_READS).
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = CUSTOM_READS_INDEX != 0 ? READS_INDEX_TSTF : READS_GRADIENT_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = false;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = true;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

float customCompositor(const int count, const float density[MAX_TIME_STEPS], const bool hasData[MAX_TIME_STEPS],
                       const bool inMask[MAX_TIME_STEPS], const vec4 stf[MAX_TIME_STEPS],
                       const float time[MAX_TIME_STEPS]) {
#include "custom_compositor_body.glsl"
}

// The time-steps the walk meets wait here, indexed by time-step and marked with the sample's
// generation instead of cleared (as in tc_chronovolume.glsl).
TimeStepSample customSample[MAX_TIME_STEPS];
int customMark[MAX_TIME_STEPS];
int customGeneration = 0;

struct CompositorState {
    int met;
};

CompositorState compositorInit() {
    customGeneration += 1;
    return CompositorState(0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    customSample[s.step] = s;
    customMark[s.step] = customGeneration;
    state.met += 1;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.met == 0) return transparentCharacteristic();
    float density[MAX_TIME_STEPS];
    bool hasData[MAX_TIME_STEPS];
    bool inMask[MAX_TIME_STEPS];
    vec4 stf[MAX_TIME_STEPS];
    float time[MAX_TIME_STEPS];
    int strongest = -1;
    bool anyInMask = false;
    for (int step = 0; step < timeStepCount; ++step) {
        hasData[step] = customMark[step] == customGeneration;
        density[step] = hasData[step] ? customSample[step].density : 0.0;
        inMask[step] = hasData[step] && customSample[step].inMask;
        stf[step] = hasData[step] ? customSample[step].stf : vec4(0.0);
        time[step] = timeSteps.steps[step].time.x;
        anyInMask = anyInMask || inMask[step];
        if (hasData[step] && (strongest < 0 || stf[step].a > stf[strongest].a)) strongest = step;
    }
    float value = customCompositor(timeStepCount, density, hasData, inMask, stf, time);
    if (isnan(value) || isinf(value)) return transparentCharacteristic();
#if CUSTOM_READS_INDEX
    int step = int(round(value));
    if (step < 0 || step >= timeStepCount || !hasData[step] || stf[step].a <= 0.0)
        return transparentCharacteristic();
    return characteristicOf(READS_INDEX_TSTF, float(step), customSample[step]);
#else
    if (strongest < 0 || stf[strongest].a <= 0.0) return transparentCharacteristic();
    TimeStepSample representative = customSample[strongest];
    representative.inMask = anyInMask;
    return characteristicOf(READS_GRADIENT_TSTF, value, representative);
#endif
}
