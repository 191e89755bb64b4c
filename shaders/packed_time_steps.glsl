// Fully aligned series (render/packed_aligned_atlas.h): four consecutive time-steps share one
// RGBA16 texel of the packed atlas, so one filtered fetch reads a group of four at a sample. All
// time-steps have the same grid, placement and entry/exit interval, so the ray's first slot gives
// the voxel position of every one of them, and one occupancy texel per brick (visible where any
// time-step is) decides empty-space skipping for all of them at once.
#ifndef PACKED_ALIGNED
#define PACKED_ALIGNED 0
#endif

#if PACKED_ALIGNED
layout(binding = PACKED_ATLAS_UNIT) uniform sampler3D packedAtlas;
layout(binding = PACKED_OCCUPANCY_UNIT) uniform sampler3D packedOccupancy;
uniform vec3 inversePackedAtlasSize;
uniform int packedGroupCount;

layout(std430, binding = PACKED_GROUP_BUFFER) readonly buffer PackedGroups {
    vec4 origin[];  // xyz: first texel of each group of four time-steps in the packed atlas
} packedGroups;

// The voxel position, shared by every time-step, of the sample at ray parameter t (slot 0 is
// filled whenever the ray takes a sample).
vec3 alignedVoxelAtSample(float t) {
    return clamp(activeVoxelOrigin[0] + t * activeVoxelDirection[0], vec3(0.0), activeVoxelUpper[0]);
}

// The densities of time-steps 4 group .. 4 group + 3 at the voxel position.
vec4 packedDensities(int group, vec3 voxel) {
    return texture(packedAtlas, (packedGroups.origin[group].xyz + voxel + 0.5) * inversePackedAtlasSize);
}

// Empty-space skipping for all time-steps at once: -1 when any time-step's brick at the sample is
// visible, else where the brick ends (time-step 0's grid is every time-step's grid).
float packedEmptySpaceUntil(float t) {
    vec3 voxel = alignedVoxelAtSample(t);
    if (texelFetch(packedOccupancy, ivec3(brickOf(0, voxel)), 0).r > 0.5) return -1.0;
    return brickExit(0, voxel, t, activeVoxelDirection[0]);
}
#endif
