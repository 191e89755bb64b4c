// The style transfer function (STF, over density) and the two temporal style transfer functions
// (TSTF): time-step index and gradient magnitude. Each returns vec4(colour, opacity), the opacity
// being per reference length (the finest voxel spacing of the series).
#include "contract.glsl"
layout(binding = STF_UNIT) uniform sampler1D stfTable;
layout(binding = GRADIENT_TSTF_UNIT) uniform sampler1D gradientTstfTable;
#include "raycast_uniforms.glsl"

layout(std430, binding = INDEX_TSTF_BUFFER) readonly buffer IndexTstf {
    vec4 colorOpacity[];
} indexTstf;

// Table entry i holds the function at i / (size - 1); read between texel centres.
vec4 lookupTable(sampler1D table, float x) {
    float coordinate = (clamp(x, 0.0, 1.0) * (transferTableSize - 1.0) + 0.5) / transferTableSize;
    return texture(table, coordinate);
}

vec4 classifyStf(float density) {
    return lookupTable(stfTable, density);
}

vec4 classifyIndexTstf(int step) {
    return indexTstf.colorOpacity[step];
}

// Its opacity alone: one read of the buffer where the whole entry is four (llvmpipe gathers each
// component of a read indexed per pixel).
float indexTstfOpacity(int step) {
    return indexTstf.colorOpacity[step].a;
}

vec4 classifyGradientTstf(float normalizedChange) {
    return lookupTable(gradientTstfTable, normalizedChange);
}
