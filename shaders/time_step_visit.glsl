// What every walk over the time-steps does with one time-step at a sample: count it, leave it out
// where it has no data, classify it and hand it to the compositor (compositor.glsl stands for the
// program's compositor module, tc_*.glsl).
#include "variant_switches.glsl"
#include "volume_sampling.glsl"
#include "transfer_functions.glsl"
#include "temporal_sample.glsl"
#include "compositor.glsl"

struct TemporalSample {
    TemporalCharacteristic characteristic;  // the compositor's, for the ray mode to style
    int contributing;   // how many time-steps contain the sample
    int fetches;        // volume texture fetches spent
    // > 0 when every time-step at the sample is in an empty brick: the ray may skip to here.
    float emptyUntil;
    // > 0 (SKIP_UNCHANGING_BRICKS) when no place in the sample's brick changes over time by more
    // than the ray's change floor: the ray may skip to here.
    float unchangingUntil;
};

// Densities outside stfVisibleRange have STF opacity 0 (render/transfer_tables.h, visibleDensityRange).

bool stfMayBeVisible(float density) {
    return density >= stfVisibleRange.x && density <= stfVisibleRange.y;
}

// `atlasSample`: the time-step's density and mask at the sample; `position`: the sample in the world.
void visitTimeStep(inout CompositorState state, int step, AtlasSample atlasSample, vec3 position,
                   inout TemporalSample result) {
    result.contributing += 1;
    // No data here: transparent, and left out of the temporal characteristic.
    if (isMissingDensity(atlasSample.density)) return;
    // Transparent under the STF: a compositor that leaves such time-steps out needs neither the STF
    // lookup nor its own work (llvmpipe skips them for 8-pixel blocks that agree).
    if (COMPOSITOR_IGNORES_TRANSPARENT && !stfMayBeVisible(atlasSample.density)) return;
    // A compositor that ranks by density classifies only the time-step it keeps.
    vec4 stf = COMPOSITOR_CLASSIFIES_ITSELF ? vec4(0.0) : classifyStf(atlasSample.density);
    compositorAccumulate(state, TimeStepSample(step, atlasSample.density, stf, atlasSample.inMask), position, result.fetches);
}

// A time-step the walk knows to be transparent under the STF here (a packed group whose bit the
// brick's group mask lacks), for a compositor that needs its density but not the colour of its
// transparent STF (!COMPOSITOR_READS_TRANSPARENT_COLOUR): handed over with a zero STF, without
// the lookup.
void visitTransparentTimeStep(inout CompositorState state, int step, AtlasSample atlasSample, vec3 position,
                              inout TemporalSample result) {
    result.contributing += 1;
    if (isMissingDensity(atlasSample.density)) return;
    compositorAccumulate(state, TimeStepSample(step, atlasSample.density, vec4(0.0), atlasSample.inMask), position,
                         result.fetches);
}
