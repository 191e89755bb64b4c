// Density and mask lookups in the volume atlas, where all time-steps are packed into one 3D texture.
layout(binding = ATLAS_UNIT) uniform sampler3D densityAtlas;
layout(binding = MASK_ATLAS_UNIT) uniform sampler3D maskAtlas;
uniform vec3 inverseAtlasSize;

// Voxel coordinates of a world position in a time-step's grid, clamped to the grid: samples sit
// on texel centres, and clamping to [0, dims - 1] keeps trilinear filtering inside the time-step's
// own brick, so bricks need no border between them.
vec3 voxelCoordinate(int step, vec3 worldPosition) {
    vec3 voxel = (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz;
    return clamp(voxel, vec3(0.0), timeSteps.steps[step].dims.xyz - 1.0);
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
