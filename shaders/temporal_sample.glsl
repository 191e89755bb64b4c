// The interface between the walk over the time-steps at a sample and a temporal compositor
// (paper 5.3). The walk hands every time-step with data at the sample to the compositor as a
// TimeStepSample; the compositor's finish returns a TemporalCharacteristic, which names the transfer
// function that reads it; styledCharacteristic() applies that transfer function, the styles and
// the final processing. A compositor module (tc_*.glsl) defines
//   struct CompositorState
//   CompositorState compositorInit()
//   void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches)
//   TemporalCharacteristic compositorFinish(CompositorState state)
// and nothing else that the raycaster calls.
#include "variant_switches.glsl"
#include "transfer_functions.glsl"
#include "final_processing.glsl"
#include "styles.glsl"
#include "gradient.glsl"

// One time-step at the sample. Time-steps without data there never reach a compositor.
struct TimeStepSample {
    int step;
    float density;
    vec4 stf;     // the STF's colour and opacity for `density`
    bool inMask;  // inside the time-step's segmentation mask (everywhere when it has none)
};

// Which transfer function reads a compositor's characteristic.
const int READS_NOTHING = 0;        // the sample is transparent
const int READS_STF = 1;            // the representative time-step's STF alone
const int READS_INDEX_TSTF = 2;     // the index TSTF at the representative time-step
const int READS_GRADIENT_TSTF = 3;  // the gradient TSTF at `value`, scaled by its range
const int READS_COMPOSITED = 4;     // `colorOpacity` is the finished sample (styled per time-step)

struct TemporalCharacteristic {
    int reads;
    float value;  // READS_GRADIENT_TSTF: the characteristic, in density units (per time unit for a trend)
    // The time-step whose density, STF, mask and gradient (for styles) the sample shows.
    TimeStepSample representative;
    vec4 colorOpacity;  // READS_COMPOSITED
};

TimeStepSample noTimeStep() {
    return TimeStepSample(-1, 0.0, vec4(0.0), false);
}

TemporalCharacteristic transparentCharacteristic() {
    return TemporalCharacteristic(READS_NOTHING, 0.0, noTimeStep(), vec4(0.0));
}

TemporalCharacteristic characteristicOf(int reads, float value, TimeStepSample representative) {
    return TemporalCharacteristic(reads, value, representative, vec4(0.0));
}

TemporalCharacteristic compositedCharacteristic(vec4 colorOpacity) {
    return TemporalCharacteristic(READS_COMPOSITED, 0.0, noTimeStep(), colorOpacity);
}

// Where the time-step's style is read at this sample (6 fetches when styled).
SphereCoordinate styleCoordinate(int step, vec3 position, inout int fetches) {
#if STYLED
    fetches += 6;
    return sphereCoordinate(worldGradient(step, position));
#else
    return SphereCoordinate(vec2(0.5));
#endif
}

// One time-step's own temporal style: its STF and its index TSTF, styled, after final processing.
vec4 styledTimeStep(TimeStepSample s, vec3 position, inout int fetches) {
    vec4 tstf = classifyIndexTstf(s.step);
    SphereCoordinate sphere = styleCoordinate(s.step, position, fetches);
    return finalProcessing(applyStyle(STF_TRACK, s.density, s.stf, sphere),
                           applyStyle(INDEX_TSTF_TRACK, float(s.step), tstf, sphere), s.inMask);
}

// The gradient TSTF's range: `value` from [changeRange.x, changeRange.y] goes to [0, 1].
uniform vec2 changeRange;

// The sample's colour and opacity for a compositor's characteristic.
vec4 styledCharacteristic(TemporalCharacteristic c, vec3 position, inout int fetches) {
    if (c.reads == READS_NOTHING) return vec4(0.0);
    if (c.reads == READS_COMPOSITED) return c.colorOpacity;
    if (c.reads == READS_INDEX_TSTF) return styledTimeStep(c.representative, position, fetches);
    SphereCoordinate sphere = styleCoordinate(c.representative.step, position, fetches);
    vec4 stf = applyStyle(STF_TRACK, c.representative.density, c.representative.stf, sphere);
    if (c.reads == READS_STF) return stf;
    float scaled = (c.value - changeRange.x) / (changeRange.y - changeRange.x);
    vec4 tstf = applyStyle(GRADIENT_TSTF_TRACK, clamp(scaled, 0.0, 1.0), classifyGradientTstf(scaled), sphere);
    return finalProcessing(stf, tstf, c.representative.inMask);
}
