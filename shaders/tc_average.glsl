// Temporal average (paper 5.3): every time-step with some opacity is styled on its own (its STF and
// its index TSTF); opacities are averaged, and colours are averaged weighted by opacity, so a faint
// time-step does not wash out the colour of an opaque one.
// With PER_RAY_CACHES (llvmpipe) the time-steps that read a lit sphere are styled in the finish,
// not as the walk meets them: inside the ray's loop llvmpipe runs the styling code for all 8 pixels
// it shades together whether any of them needs it or not, so styling in the walk ran once for every
// time-step that any of the 8 saw, and in the finish it runs as often as the pixel with the most
// time-steps to style needs; the others (outside the masks of a scene whose STF has no styles, or
// every time-step of a flat scene) need no style code and are added as the walk meets them. On a
// GPU the arrays that this takes cost more than the styling saves (docs/performance.md, "On a GPU").
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_COMPOSITED;
const bool COMPOSITOR_IGNORES_TRANSPARENT = true;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = false;

// The styled time-steps added so far: the sum of their premultiplied colours and opacities, and
// how many have some opacity.
struct AverageSums {
    vec4 premultipliedSum;
    int nonTransparent;
};

void addStyled(inout AverageSums sums, vec4 styled) {
    if (styled.a <= 0.0) return;
    sums.premultipliedSum += vec4(styled.rgb * styled.a, styled.a);
    sums.nonTransparent += 1;
}

// Their average: colour weighted by opacity, opacity averaged.
TemporalCharacteristic averageOf(AverageSums sums) {
    if (sums.nonTransparent == 0) return transparentCharacteristic();
    vec4 sum = sums.premultipliedSum;
    return compositedCharacteristic(vec4(sum.rgb / sum.a, sum.a / float(sums.nonTransparent)));
}

#if PER_RAY_CACHES
// The visible time-steps of the sample whose styling reads a lit sphere, in the order the walk met
// them. The others are added as the walk meets them: with no style code in the walk the sums add
// up in another order than on a GPU, which only rounding shows.
int averageStep[MAX_TIME_STEPS];
float averageDensity[MAX_TIME_STEPS];
bool averageInMask[MAX_TIME_STEPS];

struct CompositorState {
    AverageSums sums;
    int deferred;  // entries of the arrays above
};

CompositorState compositorInit() {
    return CompositorState(AverageSums(vec4(0.0), 0), 0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (s.stf.a <= 0.0) return;
    if (!readsLitSphere(s.inMask, INDEX_TSTF_TRACK)) {
        addStyled(state.sums, timeStepWithoutStyles(s));
        return;
    }
    averageStep[state.deferred] = s.step;
    averageDensity[state.deferred] = s.density;
    averageInMask[state.deferred] = s.inMask;
    state.deferred += 1;
}

// llvmpipe runs the styling in this loop for all 8 pixels it shades together, as often as the one
// with the most time-steps left to style needs: where styles show inside the masks only (an
// unstyled STF), that is seldom more than once (docs/performance.md, "The sonar's temporal average:
// styling only what reads a lit sphere").
TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    for (int i = 0; i < state.deferred; ++i) {
        float density = averageDensity[i];
        addStyled(state.sums, styledTimeStep(TimeStepSample(averageStep[i], density, classifyStf(density), averageInMask[i]),
                                             position, fetches));
    }
    return averageOf(state.sums);
}
#else
// On a GPU each visible time-step is styled as the walk meets it, into running sums: the arrays of
// the finish would live in slow per-thread memory there.
struct CompositorState {
    AverageSums sums;
};

CompositorState compositorInit() {
    return CompositorState(AverageSums(vec4(0.0), 0));
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (s.stf.a <= 0.0) return;
    addStyled(state.sums, styledTimeStep(s, position, fetches));
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    return averageOf(state.sums);
}
#endif
