#version 450 core
// Precomputed gradients for lit-sphere styles (gradient.glsl, PRECOMPUTED_GRADIENTS): one
// invocation per voxel of one time-step's brick writes the density's central differences at that
// node, one voxel apart in its own grid (one-sided at the brick's faces), into the gradient atlas,
// which has the density atlas' layout. Trilinear filtering of these node differences is, in exact
// arithmetic, the on-the-fly gradient of worldGradient() at every position at least one voxel
// inside the grid: there both are differences of trilinear interpolation with the same weights.
// Within a voxel of a face the on-the-fly difference narrows its span; the filtered one blends the
// face's one-sided difference with the next node's central one. Only for series whose grids are
// all even rectilinear (voxel coordinates affine in world position) and have no missing values.
#include "contract.glsl"
#include "time_steps.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;

layout(binding = ATLAS_UNIT) uniform sampler3D densityAtlas;
layout(binding = GRADIENT_IMAGE_UNIT, rgba16f) uniform writeonly restrict image3D gradientAtlas;

uniform int step;  // the time-step whose brick this dispatch covers

void main() {
    ivec3 dims = ivec3(timeSteps.steps[step].dims.xyz);
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, dims))) return;
    ivec3 brickOrigin = ivec3(timeSteps.steps[step].brickOrigin.xyz);
    vec3 gradient;
    for (int axis = 0; axis < 3; ++axis) {
        ivec3 offset = ivec3(0);
        offset[axis] = 1;
        ivec3 upper = min(voxel + offset, dims - 1);
        ivec3 lower = max(voxel - offset, ivec3(0));
        int span = upper[axis] - lower[axis];
        float difference = texelFetch(densityAtlas, brickOrigin + upper, 0).r -
                           texelFetch(densityAtlas, brickOrigin + lower, 0).r;
        gradient[axis] = span > 0 ? difference / float(span) : 0.0;
    }
    imageStore(gradientAtlas, brickOrigin + voxel, vec4(gradient, 0.0));
}
