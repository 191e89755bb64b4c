// Ray mode "average": the mean along the ray of the samples' temporal styles. The colour is the
// mean of the samples' colours, each weighted by its opacity and its segment's length; the opacity
// is the mean of the samples' opacities (per reference length, as the transfer functions give them)
// over the length of the ray inside the series, transparent stretches counted. A constant shows as
// its own colour and opacity, however thick.
#include "ray_sample.glsl"

struct RayState {
    vec3 weightedColour;  // sum of colour x opacity x length
    float weightedOpacity;  // sum of opacity x length
    float insideLength;   // of the ray inside the series
};

RayState rayInit(Ray ray) {
    return RayState(vec3(0.0), 0.0, 0.0);
}

void rayAccumulate(inout RayState state, RaySample s, inout int fetches) {
    state.insideLength += s.segmentLength;
    vec4 styled = styledSample(s, fetches);
    float opacity = clamp(styled.a, 0.0, 1.0);
    state.weightedColour += styled.rgb * opacity * s.segmentLength;
    state.weightedOpacity += opacity * s.segmentLength;
}

void rayPassEmpty(inout RayState state, float skippedLength) {
    state.insideLength += skippedLength;
}

void rayPassGap(inout RayState state) {}

bool rayDone(RayState state) {
    return false;
}

vec4 rayFinish(inout RayState state, inout int fetches) {
    if (state.weightedOpacity <= 0.0) return vec4(0.0);
    float opacity = state.weightedOpacity / state.insideLength;
    return vec4(state.weightedColour / state.weightedOpacity * opacity, opacity);
}
