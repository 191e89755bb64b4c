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
        // A place whose time shows (READS_INDEX_TSTF) is styled with its time colour and as opaque
        // as a slab `changedGain` times as thick; an unchanged one (READS_STF, no time colour, as
        // final processing shows it outside a mask) with the STF alone, as opaque as the scene asks,
        // and where `unchangedBoundary` is set, fading to UNCHANGED_INTERIOR of that inside regions
        // of one value. One styledFinalOn for both and one gradient for the style and the boundary:
        // llvmpipe runs both sides of a branch.
        bool timed = c.reads == READS_INDEX_TSTF;
        TimeStepSample shown = c.representative;
        shown.inMask = timed && shown.inMask;
        bool boundaryRead = !timed && unchangedBoundary > 0.0;
        vec3 gradient = vec3(0.0);
        if (boundaryRead || (STYLED != 0 && readsLitSphere(shown.inMask, INDEX_TSTF_TRACK)))
            gradient = countedGradient(shown.step, position, fetches);
        SphereCoordinate sphere = STYLED != 0 ? sphereCoordinate(gradient) : SphereCoordinate(vec2(0.5));
        vec4 styled = styledFinalOn(sphere, shown, timed ? classifyIndexTstf(shown.step) : vec4(0.0),
                                    INDEX_TSTF_TRACK, timed ? float(shown.step) : 0.0);
        if (timed) return vec4(styled.rgb, 1.0 - pow(1.0 - clamp(styled.a, 0.0, 1.0), changedGain));
        float share = unchangedOpacity;
        if (boundaryRead)
            share *= mix(UNCHANGED_INTERIOR, 1.0, clamp(length(gradient) / unchangedBoundary, 0.0, 1.0));
        return vec4(styled.rgb, styled.a * share);
    }
    // READS_STF: the representative's STF alone, as final processing shows it outside a mask.
    TimeStepSample shown = c.representative;
    if (c.reads == READS_STF) shown.inMask = false;
    float scaled = (c.value - changeRange.x) / (changeRange.y - changeRange.x);
    return styledFinal(shown, position, classifyGradientTstf(scaled), GRADIENT_TSTF_TRACK, clamp(scaled, 0.0, 1.0),
                       fetches);
}
