// Fully aligned series (render/packed_aligned_atlas.h): four consecutive time-steps share one
// RGBA16 texel of the packed atlas, so one filtered fetch reads a group of four at a sample. All
// time-steps have the same grid, placement and entry/exit interval, so the ray's only slot gives
// the voxel position of every one of them (one node lookup along uneven axes for all), and one
// occupancy texel per brick (visible where any time-step is; else how far the empty bricks reach)
// decides empty-space skipping for all of them at once. Included by the packed walk of the
// time-steps (walk_packed_groups.glsl) only.
// With missing values the packed densities are premultiplied by validity (render::PackedValidity):
// PER_GROUP: the group's four validities are a second RGBA16 texel at the same place; SHARED:
// every time-step misses the same voxels, and one R16 texture of the grid holds their validity.
// The switch PACKED_VALIDITY holds one of the PACKED_VALIDITY_* codes of contract.glsl; the tests
// of it below are constant, so the compiler keeps only the code of the one that holds.
#include "contract.glsl"
#include "variant_switches.glsl"
#include "volume_sampling.glsl"
#include "voxel_rays.glsl"

layout(binding = PACKED_ATLAS_UNIT) uniform sampler3D packedAtlas;
// Per brick without PACKED_GROUP_MASKS: how far the empty bricks reach (emptyReachOfTexel).
layout(binding = PACKED_OCCUPANCY_UNIT) uniform usampler3D packedOccupancy;
// Per brick with PACKED_GROUP_MASKS: r, the occupancy texel; g, bit g set where
// a time-step of group g is visible under the STF. One fetch gives a sample both.
layout(binding = PACKED_GROUP_MASK_UNIT) uniform usampler3D packedGroupMasks;
layout(binding = PACKED_VALIDITY_UNIT) uniform sampler3D packedValidity;
#if SKIP_UNCHANGING_BRICKS
// Per brick: at least the range over time of the densities at any place in it (render::
// brickChangeBounds, raised by the 16-bit rounding).
layout(binding = PACKED_CHANGE_BOUND_UNIT) uniform sampler3D packedChangeBounds;
#endif
#include "raycast_uniforms.glsl"

layout(std430, binding = PACKED_GROUP_BUFFER) readonly buffer PackedGroups {
    vec4 origin[];  // xyz: first texel of each group of four time-steps in the packed atlas
} packedGroups;

// The sample in the grid every time-step shares (slot 0 is filled whenever the ray takes a
// sample): `gridLocal` in worldToVoxel's space, `voxel` after the node lookup along uneven axes
// (one lookup for all time-steps), clamped to the grid; `brick`: the texel of packedGroupMasks of
// the brick it lies in (PACKED_GROUP_MASKS).
struct AlignedSample {
    vec3 gridLocal;
    vec3 voxel;
    uvec2 brick;
};

uvec2 brickTexelAt(vec3 voxel) {
#if PACKED_GROUP_MASKS
    return texelFetch(packedGroupMasks, ivec3(brickOf(0, voxel)), 0).rg;
#else
    return uvec2(0u);
#endif
}

#if UNEVEN_AXES
// The shared grid's uneven-axis lookup and node counts, read once per ray (prepareAlignedSamples)
// rather than from the storage buffers at every sample.
UnevenAxisInfo alignedUnevenAxes;
ivec3 alignedNodes;
#endif

// After prepareVoxelRays.
void prepareAlignedSamples() {
#if UNEVEN_AXES
    alignedUnevenAxes = unevenAxes.steps[activeSteps[0]];
    alignedNodes = ivec3(timeSteps.steps[activeSteps[0]].dims.xyz);
#endif
}

AlignedSample alignedSampleAt(float t) {
    vec3 gridLocal = gridLocalAtSample(0, t);
#if ALL_AFFINE
    vec3 voxel = clamp(gridLocal, vec3(0.0), slotVoxelUpper(0));
    return AlignedSample(voxel, voxel, brickTexelAt(voxel));
#else
#if UNEVEN_AXES
    vec3 voxel = applyUnevenAxesIn(alignedUnevenAxes, alignedNodes, gridLocal);
#else
    vec3 voxel = gridLocal;
#endif
    voxel = clamp(voxel, vec3(0.0), slotVoxelUpper(0));
    return AlignedSample(gridLocal, voxel, brickTexelAt(voxel));
#endif
}

// Fetches per sample for the shared validity, and per group of four time-steps.
const int PACKED_FETCHES_PER_SAMPLE = PACKED_VALIDITY == PACKED_VALIDITY_SHARED ? 1 : 0;
const int PACKED_FETCHES_PER_GROUP = PACKED_VALIDITY == PACKED_VALIDITY_PER_GROUP ? 2 : 1;

// The validity every time-step has at the voxel position (PACKED_VALIDITY_SHARED), else 1.
float sharedValidityAt(vec3 voxel) {
    if (PACKED_VALIDITY != PACKED_VALIDITY_SHARED) return 1.0;
    return texture(packedValidity, (voxel + 0.5) * inverseSharedValiditySize).r;
}

// The densities of time-steps 4 group .. 4 group + 3 at the voxel position; MISSING_DENSITY where
// a time-step has no data there (as sampleDensity decides for one time-step).
vec4 packedDensities(int group, vec3 voxel, float sharedValidity) {
    vec3 position = (packedGroups.origin[group].xyz + voxel + 0.5) * inversePackedAtlasSize;
    vec4 densities = texture(packedAtlas, position);
    if (PACKED_VALIDITY == PACKED_VALIDITY_NONE) return densities;
    vec4 validity =
        PACKED_VALIDITY == PACKED_VALIDITY_PER_GROUP ? texture(packedValidity, position) : vec4(sharedValidity);
    return mix(densities / validity, vec4(MISSING_DENSITY), lessThan(validity, vec4(0.5)));
}

// The groups with a time-step visible in the sample's brick (PACKED_GROUP_MASKS).
uint visibleGroupsAt(AlignedSample aligned) {
    return aligned.brick.y;
}

// Empty-space skipping for all time-steps at once: -1 when any time-step's brick at the sample is
// visible, else where the brick ends (time-step 0's grid is every time-step's grid).
float packedEmptySpaceUntil(AlignedSample aligned, float t) {
#if !SKIP_EMPTY_BRICKS
    return -1.0;
#endif
#if PACKED_GROUP_MASKS
    int reach = emptyReachOfTexel(aligned.brick.x);
#else
    int reach = emptyReachOfTexel(texelFetch(packedOccupancy, ivec3(brickOf(0, aligned.voxel)), 0).r);
#endif
    if (reach < 0) return -1.0;
    return brickExit(0, aligned.voxel, aligned.gridLocal, t, slotVoxelDirection(0), reach);
}

#if SKIP_UNCHANGING_BRICKS
// Skipping the bricks that cannot change a largest-change ray's pixel: -1 where the brick at the
// sample may hold a place whose densities span more than `changeFloor` over time, else where the
// brick ends. A compositor that sees one time-step alone (one exposed) reports a change above any
// bound, so then never.
float packedUnchangingSpaceUntil(AlignedSample aligned, float t, float changeFloor) {
    if (exposedSteps.x >= exposedSteps.y) return -1.0;
    if (texelFetch(packedChangeBounds, ivec3(brickOf(0, aligned.voxel)), 0).r > changeFloor) return -1.0;
    return brickExit(0, aligned.voxel, aligned.gridLocal, t, slotVoxelDirection(0), 0);
}
#endif
