// Ray mode "largest-change": the sample that changes most over time along the ray, shown in its
// transfer functions' colour. With a compositor that picks a time-step, the change is the range of
// the densities over the time-steps (which those compositors measure with UNCHANGED_TIME: the
// renderer turns it on for this mode, RayModeInfo::readsChange), and the colour the picked
// time-step's, or the STF's grey where the place counts as unchanged: seen from above, each place
// of a map shows the time of the layer where it changes most, not a mix of every depth along the
// column. With a compositor whose value the gradient TSTF reads (a change, a spread, a trend, a
// difference), the change is that value's magnitude, in the gradient TSTF's colour. The first of
// equal changes, the nearest, stays.
#include "ray_sample.glsl"

float comparedValue(TemporalCharacteristic c) {
    return c.change;
}

bool replacesKept(float value, float keptValue) {
    return value > keptValue;
}

#include "ray_extremum.glsl"

float rayChangeFloor(RayState state) {
    return state.kept.kept ? state.kept.value : -1.0;
}
