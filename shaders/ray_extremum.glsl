// The ray modes that keep the sample with the most extreme value along the ray (maximum, minimum,
// largest change): the module includes ray_sample.glsl, defines `float comparedValue(
// TemporalCharacteristic c)`, what it compares (the characteristic's value, or its change over
// time), and `bool replacesKept(float value, float keptValue)`, whether a value met further along
// replaces the one kept (the first of equal values, the nearest, stays), then includes this file.
#include "ray_kept_sample.glsl"

struct RayState {
    KeptSample kept;
};

RayState rayInit(Ray ray) {
    return RayState(noKeptSample());
}

void rayAccumulate(inout RayState state, RaySample s, inout int fetches) {
    if (!hasValue(s.characteristic)) return;
    float value = comparedValue(s.characteristic);
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
