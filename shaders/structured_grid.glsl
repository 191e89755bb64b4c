// Explicit structured grids: a sample's computational coordinates (its voxel in the density atlas)
// come from the grid's inverse map, a 3D texture over the grid's local bounds filled on load by
// exact point location (data/inverse_map.h). The time-step's worldToVoxel takes world positions to
// the lattice of dims nodes spread over those bounds; mapScale turns that into inverse-map texels.
// 1 when the series has structured time-steps; 0 compiles every lookup below away, so that
// rectilinear series pay nothing for them.
#include "contract.glsl"
#include "variant_switches.glsl"
#include "time_steps.glsl"

layout(std430, binding = STRUCTURED_GRID_BUFFER) readonly buffer StructuredGrids {
    StructuredGridInfo steps[];
} structuredGrids;

// rgb: computational coordinates; a: 1 inside the grid, 0 outside (filtered in between).
layout(binding = INVERSE_MAP_UNIT) uniform sampler3D inverseMapAtlas;

bool isStructured(int step) {
#if STRUCTURED_GRIDS
    return ONLY_STRUCTURED_GRIDS || structuredGrids.steps[step].mapOrigin.w > 0.5;
#else
    return false;
#endif
}

vec4 inverseMapAt(int step, vec3 worldPosition) {
    StructuredGridInfo grid = structuredGrids.steps[step];
    vec3 lattice = (timeSteps.steps[step].worldToVoxel * vec4(worldPosition, 1.0)).xyz;
    // Clamped to the map's own texels so that filtering never reads a neighbouring map in the atlas.
    vec3 lastTexel = (timeSteps.steps[step].dims.xyz - 1.0) * grid.mapScale.xyz;
    vec3 texel = clamp(lattice * grid.mapScale.xyz, vec3(0.0), lastTexel);
    return texture(inverseMapAtlas, (grid.mapOrigin.xyz + texel + 0.5) / vec3(textureSize(inverseMapAtlas, 0)));
}

vec3 structuredVoxelCoordinate(int step, vec3 worldPosition) {
    return clamp(inverseMapAt(step, worldPosition).rgb, vec3(0.0), timeSteps.steps[step].dims.xyz - 1.0);
}

// Whether a sample inside a time-step's entry/exit interval is inside its grid: always for
// rectilinear grids; for structured grids the interval of a concave grid can span a gap, which
// the inverse map marks as outside (to within one map texel of the boundary).
bool insideStructuredGrid(int step, vec3 worldPosition) {
    return !isStructured(step) || inverseMapAt(step, worldPosition).a > 1.0e-3;
}
