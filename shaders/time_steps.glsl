// Per-time-step description: where its samples are in the world, where its brick is in the atlas.
struct TimeStepInfo {
    mat4 worldToVoxel;  // world position -> voxel coordinates (sample (i,j,k) sits at (i,j,k));
                        // beam grids: world -> grid-local position
    vec4 brickOrigin;   // xyz: first texel of this time-step's brick in the atlas
    vec4 dims;          // xyz: samples along each axis; w: 1 when the time-step has a mask
    ivec4 layer;        // x: layer of this time-step's proxy box in the entry/exit buffers
    vec4 occupancyOrigin;  // xyz: first texel of this time-step's bricks in the occupancy atlas
    // x: 1 when voxelCoordinate() is an affine function of the world position (even rectilinear
    // grids): only then may a ray's voxel position be stepped incrementally (shaders/voxel_rays.glsl).
    ivec4 flags;
    // x: GRID_RECTILINEAR or GRID_BEAM (beam_grid.glsl). Beam grids: y, z: where the azimuth and
    // the elevation angles start in the beam angle buffer.
    ivec4 grid;
    // Beam grids: x, y: minimum and maximum range; z: world distance of the gradient's differences.
    vec4 beamRange;
};

layout(std430, binding = TIME_STEP_BUFFER) readonly buffer TimeSteps {
    TimeStepInfo steps[];
} timeSteps;
