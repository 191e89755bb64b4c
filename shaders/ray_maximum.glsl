// Ray mode "maximum" (maximum intensity projection): the sample with the largest characteristic
// value along the ray, shown in its transfer functions' colour. With temporal-mip or time-of-max it
// is the brightest place along the ray, in the colour of the time-step when it was brightest.
#include "ray_sample.glsl"

float comparedValue(TemporalCharacteristic c) {
    return characteristicValue(c);
}

bool replacesKept(float value, float keptValue) {
    return value > keptValue;
}

#include "ray_extremum.glsl"
