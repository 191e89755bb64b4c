// Ray mode "additive": the samples' temporal styles added up along the ray, emission without
// absorption (each sample's colour times its opacity over its segment, the opacity per reference
// length times the segment's length), clamped to 1. Dense places add up to white where
// compositing would hide what lies behind them.
#include "ray_sample.glsl"

struct RayState {
    vec4 sum;  // premultiplied colour, opacity
};

RayState rayInit(Ray ray) {
    return RayState(vec4(0.0));
}

void rayAccumulate(inout RayState state, RaySample s, inout int fetches) {
    vec4 styled = styledSample(s, fetches);
    float opacity = clamp(styled.a, 0.0, 1.0) * s.segmentLength / referenceLength;
    state.sum += vec4(styled.rgb * opacity, opacity);
}

void rayPassEmpty(inout RayState state, float skippedLength) {}

void rayPassGap(inout RayState state) {}

// Once every channel is full nothing further changes the pixel: the ray may stop.
bool rayDone(RayState state) {
    return all(greaterThanEqual(state.sum, vec4(1.0)));
}

vec4 rayFinish(inout RayState state, inout int fetches) {
    return clamp(state.sum, 0.0, 1.0);
}
