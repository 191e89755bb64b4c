// Final processing (paper 5.5): return the STF value, the TSTF value or the STF modulated by the
// TSTF. Outside a segmentation mask the time-invariant STF applies.
#include "contract.glsl"

uniform int finalMode;

vec4 finalProcessing(vec4 stf, vec4 tstf, bool inRegionOfInterest) {
    if (!inRegionOfInterest || finalMode == FINAL_STF) return stf;
    if (finalMode == FINAL_TSTF) return tstf;
    return stf * tstf;
}
