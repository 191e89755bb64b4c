// The interface between the ray's march (raycast.frag) and a ray mode: how the samples along a
// ray become the pixel. At each sample the temporal compositor has already turned the time-steps
// into a temporal characteristic (temporal_compositor.glsl); the program's ray mode (ray_mode.glsl
// stands for one of the ray_*.glsl modules, RayModeInfo::shaderModule) reduces those along the ray:
// compositing front to back (the paper's), the maximum, the minimum, the average, the sum, the
// maximum attenuated by what lies in front, or the first crossings of iso-values. A ray mode module
// defines
//   struct RayState
//   RayState rayInit(Ray ray)
//   void rayAccumulate(inout RayState state, RaySample s, inout int fetches)
//                                     one sample, in front-to-back order
//   void rayPassEmpty(inout RayState state, float skippedLength)
//                                     `skippedLength` of the ray skipped as transparent under the STF
//                                     (empty bricks), where no sample was taken
//   void rayPassGap(inout RayState state)
//                                     the ray leaves every time-step (a gap between grids)
//   bool rayDone(RayState state)      nothing further along the ray can change the pixel
//   vec4 rayFinish(inout RayState state, inout int fetches)
//                                     the pixel's premultiplied colour and opacity, before the background
// and, a mode that reads the change over time (RayModeInfo::readsChange),
//   float rayChangeFloor(RayState state)
//                                     the change a sample must exceed to change the pixel, -1 while
//                                     every sample may (SKIP_UNCHANGING_BRICKS skips the rest)
// and the uniforms of its options (the table of ray modes names them, ray_modes.h).
#include "temporal_sample.glsl"
#include "characteristic_style.glsl"
#include "ray.glsl"

struct RaySample {
    TemporalCharacteristic characteristic;
    vec3 position;  // the sample's place in the world
    float t;        // its ray parameter (the middle of its segment)
    float segmentLength;  // the segment it stands for, in world units
};

// Whether the sample has a value to reduce: a compositor that found nothing to show here (no
// time-step above a threshold, all transparent) gives none.
bool hasValue(TemporalCharacteristic c) {
    return c.reads != READS_NOTHING;
}

// The value a ray mode compares along the ray: the compositor's value where the gradient TSTF reads
// it (a change, a spread, a trend, a difference: in density units), else the density of the
// time-step whose colour the sample shows (the picked time-step: the most opaque for temporal-mip,
// the densest for time-of-max). Compositors that composite the time-steps (READS_COMPOSITED) have none; the ray
// modes that need it refuse them (RayModeInfo::needsValue).
float characteristicValue(TemporalCharacteristic c) {
    if (c.reads == READS_GRADIENT_TSTF) return c.value;
    return c.representative.density;
}

// The opacity over a segment of `segmentLength` for an opacity per reference length (the paper's
// opacity correction).
float correctedOpacity(float opacity, float segmentLength) {
    return 1.0 - pow(1.0 - clamp(opacity, 0.0, 1.0), segmentLength / referenceLength);
}

// A sample's colour and opacity where a ray mode shows one sample for the whole ray (the maximum,
// the minimum, an iso-surface): as the transfer functions give it at that place.
vec4 styledSample(RaySample s, inout int fetches) {
    return styledCharacteristic(s.characteristic, s.position, fetches);
}
