#version 450 core
// Precomputed gradients for lit-sphere styles (gradient.glsl, PRECOMPUTED_GRADIENTS): for every
// node of one time-step's brick, the density's central differences one voxel apart in its own grid
// (one-sided at the brick's faces), written into the gradient atlas, which has the density atlas'
// layout. Trilinear filtering of these node differences is, in exact arithmetic, the on-the-fly
// gradient of worldGradient() at every position at least one voxel inside the grid: there both are
// differences of trilinear interpolation with the same weights. Within a voxel of a face the
// on-the-fly difference narrows its span; the filtered one blends the face's one-sided difference
// with the next node's central one. Only for series whose grids are all even rectilinear (voxel
// coordinates affine in world position) and have no missing values.
#include "contract.glsl"
#include "time_steps.glsl"

// One invocation per node; neighbouring invocations take neighbouring x, so that llvmpipe's 8 lanes
// read neighbouring texels. (A run of nodes per invocation, along x or z, was slower there.)
layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;

layout(binding = ATLAS_UNIT) uniform sampler3D densityAtlas;
layout(binding = GRADIENT_IMAGE_UNIT, rgba16f) uniform writeonly restrict image3D gradientAtlas;

uniform int step;  // the time-step whose brick this dispatch covers

float densityAt(ivec3 brickOrigin, ivec3 voxel) {
    return texelFetch(densityAtlas, brickOrigin + voxel, 0).r;
}

// The density's difference per voxel along `axis` (a unit vector) at a node: between the nodes one
// voxel to either side, or between the node and its one neighbour at a face.
float nodeDifference(ivec3 brickOrigin, ivec3 dims, ivec3 voxel, ivec3 axis) {
    ivec3 upper = min(voxel + axis, dims - 1);
    ivec3 lower = max(voxel - axis, ivec3(0));
    ivec3 apart = upper - lower;  // non-zero along `axis` only
    int span = apart.x + apart.y + apart.z;
    return span > 0 ? (densityAt(brickOrigin, upper) - densityAt(brickOrigin, lower)) / float(span) : 0.0;
}

void main() {
    ivec3 dims = ivec3(timeSteps.steps[step].dims.xyz);
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, dims))) return;
    ivec3 brickOrigin = ivec3(timeSteps.steps[step].brickOrigin.xyz);
    vec3 gradient = vec3(nodeDifference(brickOrigin, dims, voxel, ivec3(1, 0, 0)),
                         nodeDifference(brickOrigin, dims, voxel, ivec3(0, 1, 0)),
                         nodeDifference(brickOrigin, dims, voxel, ivec3(0, 0, 1)));
    imageStore(gradientAtlas, brickOrigin + voxel, vec4(gradient, 0.0));
}
