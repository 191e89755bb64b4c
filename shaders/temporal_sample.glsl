// The interface between the walk over the time-steps at a sample and a temporal compositor
// (paper 5.3). The walk hands every time-step with data at the sample to the compositor as a
// TimeStepSample; the compositor's finish returns a TemporalCharacteristic, which names the transfer
// function that reads it; styledCharacteristic() (characteristic_style.glsl) applies that transfer
// function, the styles and the final processing. A compositor module (tc_*.glsl) defines
//   const int COMPOSITOR_READS         READS_INDEX_TSTF, READS_GRADIENT_TSTF or READS_COMPOSITED
//   const bool COMPOSITOR_IGNORES_TRANSPARENT
//                                      true when compositorAccumulate leaves out every time-step
//                                      whose STF opacity is 0: the walks may then not hand those over
//   const bool COMPOSITOR_READS_TRANSPARENT_COLOUR
//                                      true when the STF colour of a time-step whose STF opacity
//                                      is 0 may change the result; false lets a walk that knows a
//                                      time-step is transparent hand it over with a zero STF,
//                                      unclassified (the packed walk's hidden groups)
//   const bool COMPOSITOR_CLASSIFIES_ITSELF
//                                      true when compositorAccumulate reads only the densities: the
//                                      walks then hand every time-step over with a zero STF, without
//                                      the lookup, and the compositor classifies the one it keeps
//   struct CompositorState
//   CompositorState compositorInit()
//   void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches)
//   TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches)
//                                      (`position`, `fetches`: as for compositorAccumulate, for a
//                                      compositor that styles the time-steps it kept only here)
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
    // How much the sample changes over time, which the largest-change ray mode compares: where a
    // compositor picked a time-step (pickedCharacteristic) with UNCHANGED_TIME, the range of the
    // densities over the time-steps at the sample (2, above every range, where only one has data:
    // the place appears or disappears); where the gradient TSTF reads the compositor's value (a
    // change, a spread, a trend, a difference), its magnitude; 0 elsewhere.
    float change;
};

TimeStepSample noTimeStep() {
    return TimeStepSample(-1, 0.0, vec4(0.0), false);
}

// The time-step whose colour and style show a characteristic of all of them (a change, a spread, a
// trend): the one with the highest STF opacity (the first met on a tie), inside the mask where any
// of them is.
struct Representative {
    TimeStepSample strongest;
    bool anyInMask;
};

Representative noRepresentative() {
    return Representative(noTimeStep(), false);
}

void noteRepresentative(inout Representative representative, TimeStepSample s) {
    representative.anyInMask = representative.anyInMask || s.inMask;
    if (s.stf.a > representative.strongest.stf.a || representative.strongest.step < 0) representative.strongest = s;
}

TimeStepSample representativeSample(Representative representative) {
    TimeStepSample shown = representative.strongest;
    shown.inMask = representative.anyInMask;
    return shown;
}

TemporalCharacteristic transparentCharacteristic() {
    return TemporalCharacteristic(READS_NOTHING, 0.0, noTimeStep(), vec4(0.0), 0.0);
}

TemporalCharacteristic characteristicOf(int reads, float value, TimeStepSample representative) {
    return TemporalCharacteristic(reads, value, representative, vec4(0.0), reads == READS_GRADIENT_TSTF ? abs(value) : 0.0);
}

TemporalCharacteristic compositedCharacteristic(vec4 colorOpacity) {
    return TemporalCharacteristic(READS_COMPOSITED, 0.0, noTimeStep(), colorOpacity, 0.0);
}

// Unchanged places (UNCHANGED_TIME, CompositorOptions::unchanged): their uniforms (unchangedBelow,
// unchangedTie, unchangedOpacity, changedGain, unchangedBoundary) are in raycast_uniforms.glsl.
#include "raycast_uniforms.glsl"
const float UNCHANGED_INTERIOR = 0.25;

// The characteristic of the time-step a compositor picked, where the densities at the sample span
// `range` and the pick is ahead of the runner-up by `margin` (pass a margin above every tie where
// the compositor has no runner-up): its index, or the STF alone where that means nothing.
TemporalCharacteristic pickedCharacteristic(TimeStepSample picked, float range, float margin) {
    int band = clamp(int(picked.density * float(UNCHANGED_DENSITY_BANDS)), 0, UNCHANGED_DENSITY_BANDS - 1);
    TemporalCharacteristic picks = characteristicOf(READS_INDEX_TSTF, float(picked.step), picked);
    if (UNCHANGED_TIME != 0 && (range <= unchangedBelow[band] || margin <= unchangedTie[band])) {
        if (unchangedOpacity <= 0.0) return transparentCharacteristic();
        picks.reads = READS_STF;
        picks.value = 0.0;
    }
    if (UNCHANGED_TIME != 0) picks.change = range;
    return picks;
}

// The world gradient of a time-step at this sample (6 fetches, 1 with precomputed gradients).
vec3 countedGradient(int step, vec3 position, inout int fetches) {
    fetches += PRECOMPUTED_GRADIENTS != 0 ? 1 : 6;
    return worldGradient(step, position);
}

// Whether the final processing of a sample, in or outside the masks, with the TSTF `tstfTrack`
// shows a track that has styles, and so reads a lit sphere.
bool readsLitSphere(bool inMask, int tstfTrack) {
    return (showsStf(inMask) && isStyledTrack(STF_TRACK)) || (showsTstf(inMask) && isStyledTrack(tstfTrack));
}

// The final processing of an STF classification and a TSTF one (`tstfTrack`), each styled where
// it has styles and is shown, read on the lit spheres at `sphere`.
vec4 styledFinalOn(SphereCoordinate sphere, TimeStepSample s, vec4 tstf, int tstfTrack, float tstfX) {
    vec4 stf = showsStf(s.inMask) ? applyStyle(STF_TRACK, s.density, s.stf, sphere) : s.stf;
    vec4 styledTstf = showsTstf(s.inMask) ? applyStyle(tstfTrack, tstfX, tstf, sphere) : tstf;
    return finalProcessing(stf, styledTstf, s.inMask);
}

// styledFinalOn() where the sphere coordinate comes from the time-step's gradient, read only where a
// style is shown: outside the masks of a scene whose STF has no styles there is none. A run-time
// test: a GPU skips the gradient where a warp agrees, but inside the ray's loop llvmpipe runs it for
// every call, taken or not (docs/performance.md, "llvmpipe and branches"), so a compositor that
// styles several time-steps per sample leaves out those that need no sphere before it calls this
// (tc_average.glsl), and a caller with two ways to style one sample calls it once.
vec4 styledFinal(TimeStepSample s, vec3 position, vec4 tstf, int tstfTrack, float tstfX, inout int fetches) {
    SphereCoordinate sphere = SphereCoordinate(vec2(0.5));
#if STYLED
    if (readsLitSphere(s.inMask, tstfTrack)) sphere = sphereCoordinate(countedGradient(s.step, position, fetches));
#endif
    return styledFinalOn(sphere, s, tstf, tstfTrack, tstfX);
}

// One time-step's own temporal style: its STF and its index TSTF, styled, after final processing.
vec4 styledTimeStep(TimeStepSample s, vec3 position, inout int fetches) {
    return styledFinal(s, position, classifyIndexTstf(s.step), INDEX_TSTF_TRACK, float(s.step), fetches);
}

// styledTimeStep() of a sample where readsLitSphere(s.inMask, INDEX_TSTF_TRACK) is false: no style
// applies there, so this is the same colour without the style code.
vec4 timeStepWithoutStyles(TimeStepSample s) {
    return finalProcessing(s.stf, classifyIndexTstf(s.step), s.inMask);
}
