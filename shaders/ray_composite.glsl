// Ray mode "composite" (paper 5.2): every sample's temporal style composited front to back with
// opacity correction for its segment's length; the ray stops once it is nearly opaque.
#include "ray_sample.glsl"

struct RayState {
    vec4 accumulated;  // premultiplied colour, opacity
};

RayState rayInit(Ray ray) {
    return RayState(vec4(0.0));
}

void rayAccumulate(inout RayState state, RaySample s, inout int fetches) {
    vec4 styled = styledSample(s, fetches);
    float opacity = clamp(styled.a, 0.0, 1.0);
    if (opacity > 0.0) {
        float corrected = 1.0 - pow(1.0 - opacity, s.segmentLength / referenceLength);
        state.accumulated += (1.0 - state.accumulated.a) * vec4(styled.rgb * corrected, corrected);
    }
}

void rayPassEmpty(inout RayState state, float skippedLength) {}

void rayPassGap(inout RayState state) {}

bool rayDone(RayState state) {
    return state.accumulated.a >= terminationOpacity;
}

vec4 rayFinish(inout RayState state, inout int fetches) {
    return state.accumulated;
}
