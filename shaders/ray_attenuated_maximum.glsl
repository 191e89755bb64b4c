// Ray mode "attenuated-maximum" (napari's attenuated_mip): the maximum of the characteristic
// values, each first attenuated by the opacity in front of it, so that a bright place behind an
// opaque one counts less and the picture keeps some depth. The opacity in front is the STF's
// (corrected for each segment's length), raised to the option `attenuation`: 0 is the plain
// maximum, larger values look less far in.
#include "ray_kept_sample.glsl"

uniform float rayAttenuation;

struct RayState {
    KeptSample kept;
    float transmittance;  // of everything in front of the next sample, under the attenuation
};

RayState rayInit(Ray ray) {
    return RayState(noKeptSample(), 1.0);
}

void rayAccumulate(inout RayState state, RaySample s, inout int fetches) {
    if (!hasValue(s.characteristic)) return;
    float value = characteristicValue(s.characteristic) * state.transmittance;
    if (!state.kept.kept || value > state.kept.value) keepSample(state.kept, s, value);
    float opacity = correctedOpacity(s.characteristic.representative.stf.a, s.segmentLength);
    state.transmittance *= pow(1.0 - opacity, rayAttenuation);
}

void rayPassEmpty(inout RayState state, float skippedLength) {}

void rayPassGap(inout RayState state) {}

bool rayDone(RayState state) {
    return false;
}

vec4 rayFinish(inout RayState state, inout int fetches) {
    return finishKeptSample(state.kept, fetches);
}
