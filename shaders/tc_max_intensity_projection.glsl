// Temporal maximum intensity projection (paper 5.3): the time-step with the highest STF opacity
// wins, and the index TSTF shows which one it is. Inside overlapping opaque bodies the STF
// opacities tie; then the time-step that the index TSTF shows most strongly wins (the focus of
// Figure 1 stays opaque where its neighbours overlap it), then the earlier time-step.
// With UNCHANGED_TIME the time-steps rank by STF opacity, then density, then time; a place whose
// densities do not change, or where the winner's density is within a tie of the runner-up's
// (overlapping bodies, noise), shows no time colour. Every time-step is then needed, transparent
// ones too: a place that is transparent at one time and faintly visible at the next has not changed.
// Where the STF's opacity never falls as density rises (STF_OPACITY_RISES), a higher density never
// has a lower opacity, so ranking by density and time alone is the same order: the STF is then
// looked up for the winner alone, once, instead of for every time-step.
#include "temporal_sample.glsl"

const int COMPOSITOR_READS = READS_INDEX_TSTF;
const bool COMPOSITOR_IGNORES_TRANSPARENT = UNCHANGED_TIME == 0;
const bool COMPOSITOR_READS_TRANSPARENT_COLOUR = false;
const bool COMPOSITOR_CLASSIFIES_ITSELF = UNCHANGED_TIME != 0 && STF_OPACITY_RISES != 0;

struct CompositorState {
    TimeStepSample winner;
    float winnerTstfOpacity;  // the index TSTF's opacity at the winner (the colour is read in the finish)
    // UNCHANGED_TIME: the second in rank, and the densities' range over all time-steps.
    TimeStepSample runnerUp;
    float lowest;
    float highest;
};

CompositorState compositorInit() {
    return CompositorState(noTimeStep(), 0.0, noTimeStep(), 2.0, -1.0);
}

// UNCHANGED_TIME's ranking: higher STF opacity, then higher density, then the earlier time-step
// (where the opacity rises with density, the first test decides nothing the second would not).
bool ranksAbove(TimeStepSample a, TimeStepSample b) {
    if (b.step < 0) return true;
    if (!COMPOSITOR_CLASSIFIES_ITSELF && a.stf.a != b.stf.a) return a.stf.a > b.stf.a;
    return a.density > b.density || (a.density == b.density && a.step < b.step);
}

void compositorAccumulate(inout CompositorState state, TimeStepSample s, vec3 position, inout int fetches) {
    if (UNCHANGED_TIME != 0) {
        state.lowest = min(state.lowest, s.density);
        state.highest = max(state.highest, s.density);
        if (ranksAbove(s, state.winner)) {
            state.runnerUp = state.winner;
            state.winner = s;
        } else if (ranksAbove(s, state.runnerUp)) {
            state.runnerUp = s;
        }
        return;
    }
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
    if (COMPOSITOR_CLASSIFIES_ITSELF && state.winner.step >= 0) state.winner.stf = classifyStf(state.winner.density);
    if (state.winner.step < 0 || state.winner.stf.a <= 0.0) return transparentCharacteristic();
    // One time-step with data: no change to measure, and nothing to tie with.
    if (state.runnerUp.step < 0) return pickedCharacteristic(state.winner, 2.0, 2.0);
    return pickedCharacteristic(state.winner, state.highest - state.lowest,
                                abs(state.winner.density - state.runnerUp.density));
}
