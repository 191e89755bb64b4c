// The one sample a ray keeps where a ray mode shows a single sample for the whole ray (maximum,
// minimum, attenuated maximum): its characteristic and place, styled only once the ray is done, so
// that a ray pays for one style (a gradient when styled) instead of one per sample.
#include "ray_sample.glsl"

struct KeptSample {
    RaySample raySample;
    float value;  // what the mode compared
    bool kept;    // false until a sample with a value is met
};

KeptSample noKeptSample() {
    return KeptSample(RaySample(transparentCharacteristic(), vec3(0.0), 0.0, 0.0), 0.0, false);
}

void keepSample(inout KeptSample kept, RaySample s, float value) {
    kept = KeptSample(s, value, true);
}

// The kept sample as the transfer functions show it there, its opacity not corrected for a
// segment's length: a maximum projection shows the brightest place's colour, as opaque as the STF
// makes that value.
vec4 finishKeptSample(KeptSample kept, inout int fetches) {
    if (!kept.kept) return vec4(0.0);
    vec4 styled = styledSample(kept.raySample, fetches);
    float opacity = clamp(styled.a, 0.0, 1.0);
    return vec4(styled.rgb * opacity, opacity);
}
