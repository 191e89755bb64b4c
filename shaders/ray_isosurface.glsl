// Ray mode "isosurface": the places where the characteristic value crosses one of up to four
// iso-values (the option `values`), each composited front to back with its opacity (`opacities`)
// until the ray is nearly opaque. A crossing is found between two samples and placed by linear
// interpolation of the value between them; the surface shows the transfer functions' colour and
// style of the side above the value (which time-step's surface the ray meets, its first arrival,
// ...), lit at the surface's gradient: by the STF's lit-sphere style where the scene has styles,
// else by a headlight. A place where the compositor gives no value counts as 0, and so does the
// ray's way into the data: a body cut by the series' box shows its cut face.
#include "ray_sample.glsl"

uniform vec4 isoValues;     // unused entries far above any value, never crossed
uniform vec4 isoOpacities;

const int ISO_VALUE_SLOTS = 4;
// A headlight's share of the colour where the surface faces away: ambient light.
const float ISO_AMBIENT = 0.25;

struct RayState {
    Ray ray;
    vec4 accumulated;  // premultiplied colour, opacity
    bool hasPrevious;  // false at the ray's way into the data, and after a gap or empty space
    float previousValue;
    float previousT;
    TemporalCharacteristic previous;
};

RayState rayInit(Ray ray) {
    return RayState(ray, vec4(0.0), false, 0.0, 0.0, transparentCharacteristic());
}

// The headlight: full light where the surface faces the viewer, ISO_AMBIENT edge-on.
float headlight(TemporalCharacteristic c, vec3 position, vec3 direction, inout int fetches) {
    fetches += PRECOMPUTED_GRADIENTS != 0 ? 1 : 6;
    vec3 gradient = worldGradient(c.representative.step, position);
    float size = length(gradient);
    if (size <= 0.0) return 1.0;
    return ISO_AMBIENT + (1.0 - ISO_AMBIENT) * abs(dot(gradient / size, direction));
}

// The surface of iso-value `slot` where the ray crosses it at `t`, shown with the characteristic
// of the side above the value.
void compositeSurface(inout RayState state, int slot, float t, TemporalCharacteristic above, inout int fetches) {
    if (above.reads == READS_NOTHING) return;
    vec3 position = state.ray.origin + state.ray.direction * t;
    // The surface's opacity is its own; the STF gives the colour and style, the TSTF (modulating)
    // its share.
    above.representative.stf.a = 1.0;
    vec4 styled = styledCharacteristic(above, position, fetches);
    vec3 colour = styled.rgb;
    if (STYLED == 0) colour *= headlight(above, position, state.ray.direction, fetches);
    float opacity = clamp(isoOpacities[slot] * styled.a, 0.0, 1.0);
    state.accumulated += (1.0 - state.accumulated.a) * vec4(colour * opacity, opacity);
}

void rayAccumulate(inout RayState state, RaySample s, inout int fetches) {
    float value = hasValue(s.characteristic) ? characteristicValue(s.characteristic) : 0.0;
    float previousValue = state.hasPrevious ? state.previousValue : 0.0;
    float previousT = state.hasPrevious ? state.previousT : s.t - 0.5 * s.segmentLength;
    // The crossings in this stretch, nearest first (at most one per iso-value).
    float done = -1.0;
    for (int pass = 0; pass < ISO_VALUE_SLOTS; ++pass) {
        int nearest = -1;
        float nearestShare = 2.0;
        for (int slot = 0; slot < ISO_VALUE_SLOTS; ++slot) {
            float iso = isoValues[slot];
            if ((previousValue < iso) == (value < iso)) continue;
            float share = (iso - previousValue) / (value - previousValue);
            if (share > done && share < nearestShare) {
                nearest = slot;
                nearestShare = share;
            }
        }
        if (nearest < 0 || state.accumulated.a >= terminationOpacity) break;
        done = nearestShare;
        TemporalCharacteristic above = value >= isoValues[nearest] ? s.characteristic : state.previous;
        compositeSurface(state, nearest, mix(previousT, s.t, nearestShare), above, fetches);
    }
    state.hasPrevious = true;
    state.previousValue = value;
    state.previousT = s.t;
    state.previous = s.characteristic;
}

void rayPassEmpty(inout RayState state, float skippedLength) {
    state.hasPrevious = false;
    state.previous = transparentCharacteristic();
}

void rayPassGap(inout RayState state) {
    state.hasPrevious = false;
    state.previous = transparentCharacteristic();
}

bool rayDone(RayState state) {
    return state.accumulated.a >= terminationOpacity;
}

vec4 rayFinish(inout RayState state, inout int fetches) {
    return state.accumulated;
}
