// Ray mode "minimum" (minimum intensity projection): the sample with the smallest characteristic
// value along the ray, among the samples the compositor gives a value (those the STF shows), in
// its transfer functions' colour: the faintest visible place along the ray.
#include "ray_sample.glsl"

float comparedValue(TemporalCharacteristic c) {
    return characteristicValue(c);
}

bool replacesKept(float value, float keptValue) {
    return value < keptValue;
}

#include "ray_extremum.glsl"
