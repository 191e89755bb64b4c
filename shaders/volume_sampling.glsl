// Density and mask lookups in the volume atlas, where all time-steps are packed into one 3D texture.
#include "beam_grid.glsl"

layout(binding = ATLAS_UNIT) uniform sampler3D densityAtlas;
layout(binding = MASK_ATLAS_UNIT) uniform sampler3D maskAtlas;
uniform vec3 inverseAtlasSize;

// Voxel coordinates of a world position in a time-step's grid, clamped to the grid: samples sit
// on texel centres, and clamping to [0, dims - 1] keeps trilinear filtering inside the time-step's
// own brick, so bricks need no border between them.
vec3 voxelCoordinate(int step, vec3 worldPosition) {
    vec3 voxel = (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz;
    if (isBeamGrid(step)) voxel = beamVoxel(step, voxel).xyz;
    return clamp(voxel, vec3(0.0), timeSteps.steps[step].dims.xyz - 1.0);
}

// Whether a sample within the time-step's entry/exit interval lies in its grid: always for boxes,
// whose proxy is exact; a beam fan's proxy encloses it only conservatively, and outside the fan the
// time-step contributes nothing.
bool insideGridShape(int step, vec3 worldPosition) {
    if (!isBeamGrid(step)) return true;
    return beamVoxel(step, (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz).w > 0.5;
}

// Whether a sample lies in the time-step's grid at all (for the naive raycaster, which has no
// entry/exit intervals).
bool insideGrid(int step, vec3 worldPosition) {
    if (isBeamGrid(step)) return insideGridShape(step, worldPosition);
    vec3 voxel = (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz;
    return all(greaterThanEqual(voxel, vec3(0.0))) && all(lessThanEqual(voxel, timeSteps.steps[step].dims.xyz - 1.0));
}

vec3 atlasCoordinateOfVoxel(int step, vec3 voxel) {
    return (timeSteps.steps[step].brickOrigin.xyz + voxel + 0.5) * inverseAtlasSize;
}

vec3 atlasCoordinate(int step, vec3 worldPosition) {
    return atlasCoordinateOfVoxel(step, voxelCoordinate(step, worldPosition));
}

float sampleDensity(vec3 atlasPosition) {
    return texture(densityAtlas, atlasPosition).r;
}

// Time-steps without a mask are region of interest everywhere.
bool insideMask(int step, vec3 atlasPosition) {
    if (timeSteps.steps[step].dims.w < 0.5) return true;
    return texture(maskAtlas, atlasPosition).r >= 0.5;
}

// Empty-space skipping: one texel per brick of BRICK_SIZE³ cells in the occupancy atlas, non-zero
// where the STF can give the brick's densities some opacity (render/brick_occupancy.h).
layout(binding = OCCUPANCY_UNIT) uniform sampler3D occupancyAtlas;
const float BRICK_SIZE = 8.0;

vec3 brickCount(int step) {
    return max(ceil((timeSteps.steps[step].dims.xyz - 1.0) / BRICK_SIZE), vec3(1.0));
}

vec3 brickOf(int step, vec3 voxel) {
    return min(floor(voxel / BRICK_SIZE), brickCount(step) - 1.0);
}

bool brickVisible(int step, vec3 voxel) {
    ivec3 texel = ivec3(timeSteps.steps[step].occupancyOrigin.xyz + brickOf(step, voxel));
    return texelFetch(occupancyAtlas, texel, 0).r > 0.5;
}

// The ray parameter at which a ray at `t`, at `voxel` in the time-step's grid and heading along
// `worldDirection`, leaves the brick it is in. Voxel coordinates are an affine function of world
// position, so t carries over unchanged.
float brickExit(int step, vec3 voxel, float t, vec3 worldPosition, vec3 worldDirection) {
    // A beam grid's voxels are not affine in world position: a conservative step instead.
    if (isBeamGrid(step)) {
        vec3 brickLower = brickOf(step, voxel) * BRICK_SIZE;
        vec3 brickUpper = min(brickLower + BRICK_SIZE, timeSteps.steps[step].dims.xyz - 1.0);
        vec3 local = (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz;
        return beamBrickExit(step, brickLower, brickUpper, local, t);
    }
    vec3 direction = mat3(timeSteps.steps[step].worldToVoxel) * worldDirection;
    vec3 lower = brickOf(step, voxel) * BRICK_SIZE;
    vec3 upper = min(lower + BRICK_SIZE, timeSteps.steps[step].dims.xyz - 1.0);
    float exit = 1.0e30;
    for (int axis = 0; axis < 3; ++axis) {
        if (abs(direction[axis]) < 1.0e-12) continue;
        float bound = direction[axis] > 0.0 ? upper[axis] : lower[axis];
        exit = min(exit, (bound - voxel[axis]) / direction[axis]);
    }
    return t + max(exit, 0.0);
}
