// The ray modes that keep the sample with the most extreme characteristic value along the ray
// (maximum, minimum): the module defines `bool replacesKept(float value, float keptValue)`, whether
// a value met further along replaces the one kept (the first of equal values, the nearest, stays),
// then includes this file.
#include "ray_kept_sample.glsl"

struct RayState {
    KeptSample kept;
};

RayState rayInit(Ray ray) {
    return RayState(noKeptSample());
}

void rayAccumulate(inout RayState state, RaySample s, inout int fetches) {
    if (!hasValue(s.characteristic)) return;
    float value = characteristicValue(s.characteristic);
    if (!state.kept.kept || replacesKept(value, state.kept.value)) keepSample(state.kept, s, value);
}

void rayPassEmpty(inout RayState state, float skippedLength) {}

void rayPassGap(inout RayState state) {}

bool rayDone(RayState state) {
    return false;
}

vec4 rayFinish(inout RayState state, inout int fetches) {
    return finishKeptSample(state.kept, fetches);
}
