// Chronovolume (Woodring and Shen, "Chronovolumes", 2003), computed live: at the sample, the
// time-steps' own temporal styles (STF and index TSTF, as the temporal average styles them) are
// composited front to back in time order, earliest in front, so that earlier time-steps occlude
// later ones where they are opaque.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_COMPOSITED;
const bool COMPOSITOR_IGNORES_TRANSPARENT = true;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

// The walk meets the time-steps in the order the ray enters their grids, not in time order: each
// visible one's colour waits here, indexed by time-step, until the finish composites them in order.
// Marked with the sample's generation instead of cleared, so a sample costs only the time-steps it
// meets. The time-steps are styled in the finish, where llvmpipe runs the style code as often as
// the pixel with the most of them needs, not once for every time-step that any of the pixels
// shaded together sees (it runs the code for all of them; as tc_average.glsl). In a styled scene
// whose STF has no styles, whose styles show inside the masks only, a time-step whose final
// processing reads no lit sphere is coloured as the walk meets it, without style code, and only
// the others wait. Elsewhere that gains nothing (a flat scene has no style code to leave out; a
// styled STF reads a lit sphere almost everywhere) and the colouring in the walk cost 3-6 % of a
// frame, so there every visible time-step waits.
const bool CHRONOVOLUME_COLOURS_IN_WALK = STYLED != 0 && (STYLED_TRACKS & (1 << STF_TRACK)) == 0;

vec4 chronovolumeColour[MAX_TIME_STEPS];
float chronovolumeDensity[MAX_TIME_STEPS];
bool chronovolumeInMask[MAX_TIME_STEPS];
int chronovolumeMark[MAX_TIME_STEPS];
int chronovolumeToStyle[MAX_TIME_STEPS];  // the time-steps left to style, as the walk met them
int chronovolumeGeneration = 0;

struct CompositorState {
    int earliest;
    int latest;
    int toStyle;  // entries of chronovolumeToStyle
};

CompositorState compositorInit() {
    chronovolumeGeneration += 1;
    return CompositorState(MAX_TIME_STEPS, -1, 0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (s.stf.a <= 0.0) return;
    chronovolumeMark[s.step] = chronovolumeGeneration;
    state.earliest = min(state.earliest, s.step);
    state.latest = max(state.latest, s.step);
    if (CHRONOVOLUME_COLOURS_IN_WALK && !readsLitSphere(s.inMask, INDEX_TSTF_TRACK)) {
        chronovolumeColour[s.step] = timeStepWithoutStyles(s);
        return;
    }
    chronovolumeDensity[s.step] = s.density;
    chronovolumeInMask[s.step] = s.inMask;
    chronovolumeToStyle[state.toStyle] = s.step;
    state.toStyle += 1;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    for (int i = 0; i < state.toStyle; ++i) {
        int step = chronovolumeToStyle[i];
        float density = chronovolumeDensity[step];
        chronovolumeColour[step] = styledTimeStep(
            TimeStepSample(step, density, classifyStf(density), chronovolumeInMask[step]), position, fetches);
    }
    vec4 accumulated = vec4(0.0);  // premultiplied
    for (int step = state.earliest; step <= state.latest; ++step) {
        if (chronovolumeMark[step] != chronovolumeGeneration) continue;
        vec4 styled = chronovolumeColour[step];
        if (styled.a <= 0.0) continue;
        styled = clamp(styled, 0.0, 1.0);
        accumulated += (1.0 - accumulated.a) * vec4(styled.rgb * styled.a, styled.a);
    }
    if (accumulated.a <= 0.0) return transparentCharacteristic();
    return compositedCharacteristic(vec4(accumulated.rgb / accumulated.a, accumulated.a));
}
