// Final processing (paper 5.5): return the STF value, the TSTF value or the STF modulated by the
// TSTF. Outside a segmentation mask the time-invariant STF applies.
#include "contract.glsl"
#include "raycast_uniforms.glsl"

// Whether finalProcessing's result depends on its STF or on its TSTF argument: a classification
// that is not shown needs no style (and no gradient for one).
bool showsStf(bool inRegionOfInterest) {
    return !inRegionOfInterest || finalMode != FINAL_TSTF;
}

bool showsTstf(bool inRegionOfInterest) {
    return inRegionOfInterest && finalMode != FINAL_STF;
}

vec4 finalProcessing(vec4 stf, vec4 tstf, bool inRegionOfInterest) {
    if (!inRegionOfInterest || finalMode == FINAL_STF) return stf;
    if (finalMode == FINAL_TSTF) return tstf;
    return stf * tstf;
}
