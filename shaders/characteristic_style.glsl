// A sample's colour and opacity from the compositor's temporal characteristic: the transfer
// function that reads it, the styles and the final processing. Which transfer function can read
// the program's compositor is a constant of its module (COMPOSITOR_READS), so only that path is in
// the program: llvmpipe runs every path of a branch, masked, and the index path alone costs a
// gradient (6 fetches) when styled.
#include "temporal_sample.glsl"
#include "compositor.glsl"
#include "raycast_uniforms.glsl"

// The sample's colour and opacity for a compositor's characteristic.
vec4 styledCharacteristic(TemporalCharacteristic c, vec3 position, inout int fetches) {
    if (c.reads == READS_NOTHING) return vec4(0.0);
    if (COMPOSITOR_READS == READS_COMPOSITED) return c.colorOpacity;
    if (COMPOSITOR_READS == READS_INDEX_TSTF) {
        if (UNCHANGED_TIME == 0) return styledTimeStep(c.representative, position, fetches);
        if (c.reads == READS_INDEX_TSTF) {
            // A place whose time shows: as opaque as a slab `changedGain` times as thick.
            vec4 timed = styledTimeStep(c.representative, position, fetches);
            return vec4(timed.rgb, 1.0 - pow(1.0 - clamp(timed.a, 0.0, 1.0), changedGain));
        }
        // No time colour (pickedCharacteristic): the STF alone, as final processing shows it outside
        // a mask, as opaque as the scene asks.
        TimeStepSample neutral = c.representative;
        neutral.inMask = false;
        vec4 stf = styledFinal(neutral, position, vec4(0.0), INDEX_TSTF_TRACK, 0.0, fetches);
        float share = unchangedOpacity;
        if (unchangedBoundary > 0.0) {
            // Boundaries stay, regions of one value fade to UNCHANGED_INTERIOR of the share (6
            // fetches; 1 with precomputed gradients).
            fetches += PRECOMPUTED_GRADIENTS != 0 ? 1 : 6;
            float steepness = clamp(length(worldGradient(neutral.step, position)) / unchangedBoundary, 0.0, 1.0);
            share *= mix(UNCHANGED_INTERIOR, 1.0, steepness);
        }
        return vec4(stf.rgb, stf.a * share);
    }
    // READS_STF: the representative's STF alone, as final processing shows it outside a mask.
    TimeStepSample shown = c.representative;
    if (c.reads == READS_STF) shown.inMask = false;
    float scaled = (c.value - changeRange.x) / (changeRange.y - changeRange.x);
    return styledFinal(shown, position, classifyGradientTstf(scaled), GRADIENT_TSTF_TRACK, clamp(scaled, 0.0, 1.0),
                       fetches);
}
