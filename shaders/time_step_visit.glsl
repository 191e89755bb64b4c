// What every walk over the time-steps does with one time-step at a sample: count it, leave it out
// where it has no data, classify it and hand it to the compositor (compositor.glsl stands for the
// program's compositor module, tc_*.glsl).
#include "variant_switches.glsl"
#include "volume_sampling.glsl"
#include "transfer_functions.glsl"
#include "temporal_sample.glsl"
#include "compositor.glsl"

struct TemporalSample {
    vec4 colorOpacity;  // colour and opacity per reference length
    int contributing;   // how many time-steps contain the sample
    int fetches;        // volume texture fetches spent
    // > 0 when every time-step at the sample is in an empty brick: the ray may skip to here.
    float emptyUntil;
};

// `atlasPosition`: where the density was read (for the mask); `position`: the sample in the world.
void visitTimeStep(inout CompositorState state, int step, vec3 atlasPosition, float density, vec3 position,
                   inout TemporalSample result) {
    result.contributing += 1;
    // No data here: transparent, and left out of the temporal characteristic.
    if (isMissingDensity(density)) return;
    bool inMask = insideMask(step, atlasPosition);
    vec4 stf = classifyStf(density);
#if HAS_MASKS
    result.fetches += timeSteps.steps[step].dims.w > 0.5 ? 1 : 0;
#endif
    compositorAccumulate(state, TimeStepSample(step, density, stf, inMask), position, result.fetches);
}
