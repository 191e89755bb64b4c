// Chronovolume (Woodring and Shen, "Chronovolumes", 2003), computed live: at the sample, the
// time-steps' own temporal styles (STF and index TSTF, as the temporal average styles them) are
// composited front to back in time order, earliest in front, so that earlier time-steps occlude
// later ones where they are opaque.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_COMPOSITED;
const bool COMPOSITOR_IGNORES_TRANSPARENT = true;

// The walk meets the time-steps in the order the ray enters their grids, not in time order: each
// visible one's density waits here, indexed by time-step, until the finish styles and composites
// them in order. Marked with the sample's generation instead of cleared, so a sample costs only the
// time-steps it meets. Styling in the finish rather than as the walk meets them runs it as often
// as the pixel with the most visible time-steps needs, not once for every time-step that any of
// the pixels shaded together sees (as tc_average.glsl).
float chronovolumeDensity[MAX_TIME_STEPS];
bool chronovolumeInMask[MAX_TIME_STEPS];
int chronovolumeMark[MAX_TIME_STEPS];
int chronovolumeGeneration = 0;

struct CompositorState {
    int earliest;
    int latest;
};

CompositorState compositorInit() {
    chronovolumeGeneration += 1;
    return CompositorState(MAX_TIME_STEPS, -1);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (s.stf.a <= 0.0) return;
    chronovolumeDensity[s.step] = s.density;
    chronovolumeInMask[s.step] = s.inMask;
    chronovolumeMark[s.step] = chronovolumeGeneration;
    state.earliest = min(state.earliest, s.step);
    state.latest = max(state.latest, s.step);
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    vec4 accumulated = vec4(0.0);  // premultiplied
    for (int step = state.earliest; step <= state.latest; ++step) {
        if (chronovolumeMark[step] != chronovolumeGeneration) continue;
        float density = chronovolumeDensity[step];
        vec4 styled = styledTimeStep(TimeStepSample(step, density, classifyStf(density), chronovolumeInMask[step]),
                                     position, fetches);
        if (styled.a <= 0.0) continue;
        styled = clamp(styled, 0.0, 1.0);
        accumulated += (1.0 - accumulated.a) * vec4(styled.rgb * styled.a, styled.a);
    }
    if (accumulated.a <= 0.0) return transparentCharacteristic();
    return compositedCharacteristic(vec4(accumulated.rgb / accumulated.a, accumulated.a));
}
