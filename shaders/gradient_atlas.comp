#version 450 core
// Precomputed gradients for lit-sphere styles (gradient.glsl, PRECOMPUTED_GRADIENTS): for every
// node of one time-step's brick, the density's central differences one node apart in its own grid
// (one-sided at the brick's faces and beside nodes without data), per voxel along even axes and per
// grid-local unit along uneven ones, as worldGradient() takes them, written into the gradient
// atlas, which has the density atlas' layout. Each texel holds (gradient, 1) at a node with data and
// (0, 0) at one without, so that a filtered fetch over the alpha gives the mean of the nodes that
// have data, as the density atlas' (density * validity, validity) pairs do.
// Along even axes the filtered node differences are, in exact arithmetic, the on-the-fly gradient
// of worldGradient() at every position at least one voxel inside the grid and away from missing
// data: there both are differences of trilinear interpolation with the same weights. Within a
// voxel of a face the on-the-fly difference narrows its span; the filtered one blends the face's
// one-sided difference with the next node's central one. Along an uneven axis the filtered
// quotients differ from the quotient of the filtered difference and span where neighbouring spans
// differ. For rectilinear grids (even or uneven), not structured or beam grids.
#include "contract.glsl"
#include "time_steps.glsl"
#include "uneven_axis_nodes.glsl"

// One invocation per node; neighbouring invocations take neighbouring x, so that llvmpipe's 8 lanes
// read neighbouring texels. (A run of nodes per invocation, along x or z, was slower there.)
layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;

// Alpha is the validity where values are missing (a swizzle of the second channel), else 1.
layout(binding = ATLAS_UNIT) uniform sampler3D densityAtlas;
layout(binding = GRADIENT_IMAGE_UNIT, rgba16f) uniform writeonly restrict image3D gradientAtlas;

uniform int step;  // the time-step whose brick this dispatch covers

// A node's density, or a negative number where it has no data (its validity is 0).
float densityAt(ivec3 brickOrigin, ivec3 voxel) {
    vec4 texel = texelFetch(densityAtlas, brickOrigin + voxel, 0);
    return texel.a < 0.5 ? -1.0 : texel.r / texel.a;
}

// The distance between two nodes along `axis`, in worldToVoxel's units (voxels, or grid-local units
// along an uneven axis).
float spanBetween(int axis, int lower, int upper) {
    if (!hasUnevenAxisNodes(step, axis)) return float(upper - lower);
    return nodePositionOf(step, axis, float(upper)) - nodePositionOf(step, axis, float(lower));
}

// The density's slope along `axis` at a node with data: between the nodes to either side, or
// between the node and its one neighbour with data, or 0 where neither has any.
float nodeDifference(ivec3 brickOrigin, ivec3 dims, ivec3 voxel, int axis, float centre) {
    ivec3 offset = ivec3(0);
    offset[axis] = 1;
    ivec3 upper = min(voxel + offset, dims - 1);
    ivec3 lower = max(voxel - offset, ivec3(0));
    float upperDensity = densityAt(brickOrigin, upper);
    float lowerDensity = densityAt(brickOrigin, lower);
    if (upperDensity < 0.0) {
        upper = voxel;
        upperDensity = centre;
    }
    if (lowerDensity < 0.0) {
        lower = voxel;
        lowerDensity = centre;
    }
    if (upper[axis] == lower[axis]) return 0.0;
    return (upperDensity - lowerDensity) / spanBetween(axis, lower[axis], upper[axis]);
}

void main() {
    ivec3 dims = ivec3(timeSteps.steps[step].dims.xyz);
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(voxel, dims))) return;
    ivec3 brickOrigin = ivec3(timeSteps.steps[step].brickOrigin.xyz);
    float centre = densityAt(brickOrigin, voxel);
    if (centre < 0.0) {
        imageStore(gradientAtlas, brickOrigin + voxel, vec4(0.0));
        return;
    }
    vec3 gradient = vec3(nodeDifference(brickOrigin, dims, voxel, 0, centre),
                         nodeDifference(brickOrigin, dims, voxel, 1, centre),
                         nodeDifference(brickOrigin, dims, voxel, 2, centre));
    imageStore(gradientAtlas, brickOrigin + voxel, vec4(gradient, 1.0));
}
