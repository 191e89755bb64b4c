// Temporal average (paper 5.3): every time-step with some opacity is styled on its own (its STF and
// its index TSTF); opacities are averaged, and colours are averaged weighted by opacity, so a faint
// time-step does not wash out the colour of an opaque one.
// With PER_RAY_CACHES (llvmpipe) the time-steps are styled in the finish, not as the walk meets
// them: llvmpipe runs a branch's body for all pixels it shades together once any of them takes it,
// so styling in the walk ran once for every time-step that any of 8 pixels saw, and in the finish
// it runs as often as the pixel with the most visible time-steps needs. On a GPU the arrays that
// this takes cost more than the styling saves (docs/performance.md, "On a GPU").
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_COMPOSITED;
const bool COMPOSITOR_IGNORES_TRANSPARENT = true;

// The average of `count` styled time-steps from the sum of their premultiplied colours and opacities:
// colour weighted by opacity, opacity averaged.
TemporalCharacteristic averageOf(vec4 premultipliedSum, int count) {
    if (count == 0) return transparentCharacteristic();
    return compositedCharacteristic(vec4(premultipliedSum.rgb / premultipliedSum.a, premultipliedSum.a / float(count)));
}

#if PER_RAY_CACHES
// The visible time-steps of the sample, in the order the walk met them (so the sums add up in the
// same order as when each was styled at once).
int averageStep[MAX_TIME_STEPS];
float averageDensity[MAX_TIME_STEPS];
bool averageInMask[MAX_TIME_STEPS];

struct CompositorState {
    int visible;
};

CompositorState compositorInit() {
    return CompositorState(0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (s.stf.a <= 0.0) return;
    averageStep[state.visible] = s.step;
    averageDensity[state.visible] = s.density;
    averageInMask[state.visible] = s.inMask;
    state.visible += 1;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    vec4 premultipliedSum = vec4(0.0);
    int nonTransparent = 0;
    for (int i = 0; i < state.visible; ++i) {
        float density = averageDensity[i];
        vec4 styled = styledTimeStep(TimeStepSample(averageStep[i], density, classifyStf(density), averageInMask[i]),
                                     position, fetches);
        if (styled.a <= 0.0) continue;
        premultipliedSum += vec4(styled.rgb * styled.a, styled.a);
        nonTransparent += 1;
    }
    return averageOf(premultipliedSum, nonTransparent);
}
#else
// On a GPU each visible time-step is styled as the walk meets it, into running sums: the arrays of
// the finish would live in slow per-thread memory there.
struct CompositorState {
    vec4 premultipliedSum;
    int nonTransparent;
};

CompositorState compositorInit() {
    return CompositorState(vec4(0.0), 0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (s.stf.a <= 0.0) return;
    vec4 styled = styledTimeStep(s, position, fetches);
    if (styled.a <= 0.0) return;
    state.premultipliedSum += vec4(styled.rgb * styled.a, styled.a);
    state.nonTransparent += 1;
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    return averageOf(state.premultipliedSum, state.nonTransparent);
}
#endif
