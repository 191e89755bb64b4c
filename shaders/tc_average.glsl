// Temporal average (paper 5.3): every time-step with some opacity is styled on its own (its STF and
// its index TSTF); opacities are averaged, and colours are averaged weighted by opacity, so a faint
// time-step does not wash out the colour of an opaque one.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_COMPOSITED;
const bool COMPOSITOR_IGNORES_TRANSPARENT = true;

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

TemporalCharacteristic compositorFinish(CompositorState state) {
    if (state.nonTransparent == 0) return transparentCharacteristic();
    return compositedCharacteristic(vec4(state.premultipliedSum.rgb / state.premultipliedSum.a,
                                         state.premultipliedSum.a / float(state.nonTransparent)));
}
