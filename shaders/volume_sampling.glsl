// Density and mask lookups in the volume atlas, where all time-steps are packed into one 3D texture.
#include "contract.glsl"
#include "variant_switches.glsl"
#include "time_steps.glsl"
#include "uneven_axes.glsl"
layout(binding = ATLAS_UNIT) uniform sampler3D densityAtlas;
#include "raycast_uniforms.glsl"

#include "structured_grid.glsl"
#include "beam_grid.glsl"

// 1 when every time-step of the series has an affine world -> voxel map (TimeStepInfo.flags.x):
// the general paths (uneven axes, other grid kinds) are left out of the program, since llvmpipe
// would run them, masked, for every sample otherwise.

// Voxel coordinates of a world position in a time-step's grid, clamped to the grid: samples sit
// on texel centres, and clamping to [0, dims - 1] keeps trilinear filtering inside the time-step's
// own brick, so bricks need no border between them. Uneven axes go through their node lists.
vec3 voxelCoordinate(int step, vec3 worldPosition) {
    vec3 voxel = (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz;
#if !ALL_AFFINE
    if (isStructured(step)) return structuredVoxelCoordinate(step, worldPosition);
    if (isBeamGrid(step))
        voxel = beamVoxel(step, voxel).xyz;
    else
        voxel = applyUnevenAxes(step, voxel);
#endif
    return clamp(voxel, vec3(0.0), timeSteps.steps[step].dims.xyz - 1.0);
}

// Whether a sample within the time-step's entry/exit interval lies in its grid: always for boxes,
// whose proxy is exact; a beam fan's proxy encloses it only conservatively, and the interval of a
// concave structured grid can span a gap. Outside, the time-step contributes nothing.
bool insideGridShape(int step, vec3 worldPosition) {
#if ALL_AFFINE
    return true;
#else
    if (isStructured(step)) return insideStructuredGrid(step, worldPosition);
    if (!isBeamGrid(step)) return true;
    return beamVoxel(step, (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz).w > 0.5;
#endif
}

// Whether a sample lies in the time-step's grid at all (for the naive raycaster, which has no
// entry/exit intervals).
bool insideGrid(int step, vec3 worldPosition) {
#if !ALL_AFFINE
    if (isStructured(step) || isBeamGrid(step)) return insideGridShape(step, worldPosition);
#endif
    vec3 gridCoordinate = (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz;
    return all(greaterThanEqual(gridCoordinate, vec3(0.0))) &&
           all(lessThanEqual(gridCoordinate, gridCoordinateLimit(step)));
}

vec3 atlasCoordinateOfVoxel(int step, vec3 voxel) {
    return (timeSteps.steps[step].brickOrigin.xyz + voxel + 0.5) * inverseAtlasSize;
}

vec3 atlasCoordinate(int step, vec3 worldPosition) {
    return atlasCoordinateOfVoxel(step, voxelCoordinate(step, worldPosition));
}

// Missing values: a series with voxels without data stores (density * validity, validity) with
// validity in alpha (a swizzle), one fetch filtering both with the same weights; other series have
// alpha 1. The density is the filtered density of the valid neighbours over their filtered weight,
// and where that weight is below one half the sample has no data.
const float MISSING_DENSITY = -1.0;

// Without missing values (MISSING_VALUES 0) no density is missing, and the atlas' alpha is 1: the
// tests and the division are left out of the program.
bool isMissingDensity(float density) {
#if !MISSING_VALUES
    return false;
#endif
    return density < 0.0;
}

float densityOfTexel(vec4 texel) {
#if !MISSING_VALUES
    return texel.r;
#endif
    return texel.a < 0.5 ? MISSING_DENSITY : texel.r / texel.a;
}

float sampleDensity(vec3 atlasPosition) {
    return densityOfTexel(texture(densityAtlas, atlasPosition));
}

// A series with masks (HAS_MASKS) holds each time-step's mask in the atlas' last channel, after
// density and validity (render/density_texels.h); time-steps without a mask have it full scale.
const int MASK_CHANNEL = MISSING_VALUES != 0 ? 2 : 1;

// One fetch of the atlas at a time-step's sample: its density, and whether the sample is inside the
// time-step's segmentation mask (everywhere in a series without masks).
struct AtlasSample {
    float density;
    bool inMask;
};

AtlasSample sampleAtlas(vec3 atlasPosition) {
    vec4 texel = texture(densityAtlas, atlasPosition);
#if HAS_MASKS
    return AtlasSample(densityOfTexel(texel), texel[MASK_CHANNEL] >= 0.5);
#else
    return AtlasSample(densityOfTexel(texel), true);
#endif
}

// Empty-space skipping: one texel per brick of BRICK_SIZE³ cells in the occupancy atlas: 0 where the
// STF can give the brick's densities some opacity (render/brick_occupancy.h), else 1 + how far the
// empty bricks around it reach (render/empty_brick_reach.h).
layout(binding = OCCUPANCY_UNIT) uniform usampler3D occupancyAtlas;
const float BRICK_SIZE = float(BRICK_CELLS);

vec3 brickCount(int step) {
    return max(ceil((timeSteps.steps[step].dims.xyz - 1.0) / BRICK_SIZE), vec3(1.0));
}

vec3 brickOf(int step, vec3 voxel) {
    return min(floor(voxel / BRICK_SIZE), brickCount(step) - 1.0);
}

// An occupancy texel (this atlas' or the packed atlas'), decoded: -1 where the brick is visible;
// else its reach r: every brick at most r bricks away along each axis is empty too.
int emptyReachOfTexel(uint occupancy) {
    return int(occupancy) - 1;
}

int emptyReachAt(int step, vec3 voxel) {
    ivec3 texel = ivec3(timeSteps.steps[step].occupancyOrigin.xyz + brickOf(step, voxel));
    return emptyReachOfTexel(texelFetch(occupancyAtlas, texel, 0).r);
}

// The node box of the empty bricks within `reach` bricks of the voxel's brick, cut by the grid.
void emptyRegionOf(int step, vec3 voxel, int reach, out vec3 lower, out vec3 upper) {
    vec3 brick = brickOf(step, voxel);
    lower = max(brick - float(reach), 0.0) * BRICK_SIZE;
    upper = min((brick + float(reach) + 1.0) * BRICK_SIZE, timeSteps.steps[step].dims.xyz - 1.0);
}

// The ray parameter at which a ray at `t`, at `voxel` in the time-step's grid and moving by
// `direction` per unit of t in worldToVoxel's space, leaves the empty bricks within `reach` of the
// brick it is in. Only for rectilinear grids, where a ray is a straight line in that space with the
// ray's own parameter; `gridLocal` is the sample in that space (the voxel itself along even axes),
// where the region's faces are taken too (node index to position is monotonic along uneven axes).
float brickExit(int step, vec3 voxel, vec3 gridLocal, float t, vec3 direction, int reach) {
    vec3 lower, upper;
    emptyRegionOf(step, voxel, reach, lower, upper);
#if !ALL_AFFINE
    nodeBoundsToGrid(step, lower, upper);
#endif
    float exit = 1.0e30;
    for (int axis = 0; axis < 3; ++axis) {
        if (abs(direction[axis]) < 1.0e-12) continue;
        float bound = direction[axis] > 0.0 ? upper[axis] : lower[axis];
        exit = min(exit, (bound - gridLocal[axis]) / direction[axis]);
    }
    return t + max(exit, 0.0);
}

// Where a ray may jump to from `t` when the time-step's brick there is empty, with `reach`
// (emptyReachAt): the exit of the empty bricks around it, or for a beam grid a conservative step
// (the distance to their region's nearest bounding plane or sphere); structured grids get no jump.
// `gridLocal` and `direction` (rectilinear grids): the sample and the ray's direction in
// worldToVoxel's space (brickExit).
float emptyBrickEnd(int step, vec3 voxel, vec3 gridLocal, float t, vec3 worldPosition, vec3 direction, int reach) {
#if !ALL_AFFINE
    if (isStructured(step)) return t;
    if (isBeamGrid(step)) {
        vec3 regionLower, regionUpper;
        emptyRegionOf(step, voxel, reach, regionLower, regionUpper);
        vec3 local = (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz;
        return beamBrickExit(step, regionLower, regionUpper, local, t);
    }
#endif
    return brickExit(step, voxel, gridLocal, t, direction, reach);
}
