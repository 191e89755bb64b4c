// Temporal maximum intensity projection (paper 5.3): the time-step with the highest STF opacity
// wins, and the index TSTF shows which one it is. Inside overlapping opaque bodies the STF
// opacities tie; then the time-step that the index TSTF shows most strongly wins (the focus of
// Figure 1 stays opaque where its neighbours overlap it), then the earlier time-step.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = true;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;

struct CompositorState {
    TimeStepSample winner;
    float winnerTstfOpacity;  // the index TSTF's opacity at the winner (the colour is read in the finish)
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep(), 0.0);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (s.stf.a < state.winner.stf.a || s.stf.a <= 0.0) return;
    float tstfOpacity = indexTstfOpacity(s.step);
    bool stronger = s.stf.a > state.winner.stf.a || tstfOpacity > state.winnerTstfOpacity ||
                    (tstfOpacity == state.winnerTstfOpacity && s.step < state.winner.step);
    if (stronger) {
        state.winner = s;
        state.winnerTstfOpacity = tstfOpacity;
    }
}

TemporalCharacteristic compositorFinish(CompositorState state, vec3 position, inout int fetches) {
    if (state.winner.step < 0) return transparentCharacteristic();
    return characteristicOf(READS_INDEX_TSTF, float(state.winner.step), state.winner);
}
