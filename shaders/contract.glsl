// The C++/GLSL contract, written once: texture units, buffer binding points, enum codes and the
// std430 structs that both sides read. Every shader that uses one of them includes it, and the C++
// side includes this same file through tstyles/render/shader_contract.h, which maps the GLSL types
// to glm and checks each struct's size with a static_assert. Only syntax that means the same in
// both languages belongs here: CONTRACT_CONSTANT lines and structs of vec4, ivec4 and mat4 members
// (16-byte aligned, so std430 and C++ lay them out alike).
#ifndef CONTRACT_CONSTANT
#define CONTRACT_CONSTANT(type, name, value) const type name = value;
#endif

// Texture units.
CONTRACT_CONSTANT(int, ATLAS_UNIT, 0)
CONTRACT_CONSTANT(int, ENTRY_EXIT_UNIT, 2)
CONTRACT_CONSTANT(int, STF_UNIT, 4)
CONTRACT_CONSTANT(int, GRADIENT_TSTF_UNIT, 5)
CONTRACT_CONSTANT(int, STYLE_UNIT, 6)
CONTRACT_CONSTANT(int, OCCUPANCY_UNIT, 7)
CONTRACT_CONSTANT(int, INVERSE_MAP_UNIT, 8)
CONTRACT_CONSTANT(int, PACKED_ATLAS_UNIT, 9)
CONTRACT_CONSTANT(int, PACKED_OCCUPANCY_UNIT, 10)
CONTRACT_CONSTANT(int, PACKED_VALIDITY_UNIT, 11)
CONTRACT_CONSTANT(int, GRADIENT_ATLAS_UNIT, 12)
CONTRACT_CONSTANT(int, UNEVEN_CELL_UNIT, 13)
CONTRACT_CONSTANT(int, PACKED_GROUP_MASK_UNIT, 14)
CONTRACT_CONSTANT(int, PACKED_CHANGE_BOUND_UNIT, 15)

// Image units (imageStore).
CONTRACT_CONSTANT(int, GRADIENT_IMAGE_UNIT, 0)

// Shader-storage buffer binding points.
CONTRACT_CONSTANT(int, TIME_STEP_BUFFER, 0)
CONTRACT_CONSTANT(int, PROXY_BUFFER, 1)
CONTRACT_CONSTANT(int, INDEX_TSTF_BUFFER, 2)
CONTRACT_CONSTANT(int, STATISTICS_BUFFER, 3)
CONTRACT_CONSTANT(int, STYLE_NODE_BUFFER, 4)
CONTRACT_CONSTANT(int, STRUCTURED_GRID_BUFFER, 5)
CONTRACT_CONSTANT(int, PROXY_MESH_BUFFER, 6)
CONTRACT_CONSTANT(int, UNEVEN_AXIS_BUFFER, 7)
CONTRACT_CONSTANT(int, AXIS_NODE_BUFFER, 8)
CONTRACT_CONSTANT(int, BEAM_ANGLE_BUFFER, 9)
CONTRACT_CONSTANT(int, PACKED_GROUP_BUFFER, 10)

// Entry buffers are cleared to NO_ENTRY and exit buffers to NO_EXIT; a pixel whose ray misses a
// proxy keeps them.
CONTRACT_CONSTANT(float, NO_ENTRY, 1.0e30)
CONTRACT_CONSTANT(float, NO_EXIT, -1.0e30)

// Cells per edge of an empty-space-skipping brick (render/brick_occupancy.h says why 4).
CONTRACT_CONSTANT(int, BRICK_CELLS, 4)

// TimeStepInfo.grid.x: the kind of a time-step's grid.
CONTRACT_CONSTANT(int, GRID_RECTILINEAR, 0)
CONTRACT_CONSTANT(int, GRID_BEAM, 1)

// The PACKED_VALIDITY switch (packed_time_steps.glsl): how a packed series holds missing values.
CONTRACT_CONSTANT(int, PACKED_VALIDITY_NONE, 0)
CONTRACT_CONSTANT(int, PACKED_VALIDITY_PER_GROUP, 1)
CONTRACT_CONSTANT(int, PACKED_VALIDITY_SHARED, 2)

// The RAYCAST_PART switch (raycast.frag): the whole raycasting pass, or one of its first parts
// alone, which `bench --stages` times to see where a frame's time goes: the ray's setup (overlap
// extraction, the walk's list) without a sample, or the march (the lattice, the walk and the
// empty-space test at every sample) without fetching or compositing, so rays run to their exit.
CONTRACT_CONSTANT(int, RAYCAST_PART_WHOLE, 0)
CONTRACT_CONSTANT(int, RAYCAST_PART_RAY_SETUP, 1)
CONTRACT_CONSTANT(int, RAYCAST_PART_MARCH, 2)

// Unchanged places (temporal_sample.glsl, CompositorOptions::unchanged): their thresholds are given
// per band of density, this many equal bands over [0, 1], so that noisier values (bone in a CT) have
// their own.
CONTRACT_CONSTANT(int, UNCHANGED_DENSITY_BANDS, 16)

// The uniform finalMode (final_processing.glsl): what a sample returns.
CONTRACT_CONSTANT(int, FINAL_STF, 0)
CONTRACT_CONSTANT(int, FINAL_TSTF, 1)
CONTRACT_CONSTANT(int, FINAL_MODULATE, 2)

// Transfer functions that may hold lit-sphere styles (styles.glsl): the STF, the index TSTF and the
// gradient TSTF; the uniform styleTracks has one entry each.
CONTRACT_CONSTANT(int, STYLE_TRACK_COUNT, 3)

// Per-time-step description: where its samples are in the world, where its brick is in the atlas.
struct TimeStepInfo {
    mat4 worldToVoxel;  // world position -> voxel coordinates (sample (i,j,k) sits at (i,j,k));
                        // beam grids: world -> grid-local position
    vec4 brickOrigin;   // xyz: first texel of this time-step's brick in the atlas
    vec4 dims;          // xyz: samples along each axis; w: 1 when the time-step has a mask
    ivec4 layer;        // x: layer of this time-step's proxy box in the entry/exit buffers
    vec4 occupancyOrigin;  // xyz: first texel of this time-step's bricks in the occupancy atlas
    // x: 1 when voxelCoordinate() is an affine function of the world position (even rectilinear
    // grids): only then may a ray's voxel position be stepped incrementally (voxel_rays.glsl).
    ivec4 flags;
    // x: GRID_RECTILINEAR or GRID_BEAM. Beam grids: y, z: where the azimuth and the elevation
    // angles start in the beam angle buffer.
    ivec4 grid;
    // Beam grids: x, y: minimum and maximum range; z: world distance of the gradient's differences;
    // w: range samples per unit of range.
    vec4 beamRange;
    // Beam grids with evenly spaced beams (EVEN_BEAMS, beam_grid.glsl): x, z: the first azimuth and
    // elevation (radians); y, w: beams per radian across and along. Worked out once here, so that a
    // sample reads them with the rest of the record instead of from the beam angle buffer.
    vec4 evenBeamFan;
    // x: the time-step's time stamp minus the series' first one, in the series' time units.
    vec4 time;
};

// Per time-step, per axis (x, y, z): where uneven_axes.glsl finds a grid-local position's node
// index along an uneven axis (render/uneven_axis_table.h).
struct UnevenAxisInfo {
    ivec4 firstNode;       // the axis' first node in the node buffer; -1 along an even axis
    ivec4 firstCell;       // its first bucket's cell record in the cell-record texture
    ivec4 bucketCount;     // buckets of equal width from its first node (at 0) to its last
    vec4 bucketsPerUnit;   // 1 / bucket width, in grid-local units
};

// A box proxy for the entry/exit buffers (proxy_geometry.glsl).
struct ProxyBox {
    mat4 gridToWorld;  // grid-local position -> world
    vec4 extent;       // xyz: the box is [0, extent] in grid-local units; w: its layer
};

// A vertex of a proxy mesh (proxy_mesh.glsl), three per triangle.
struct ProxyVertex {
    vec4 position;  // xyz: world position; w: layer in the entry/exit buffers
    vec4 normal;    // xyz: the triangle's outward normal in world space
};

// An explicit structured grid's inverse map (structured_grid.glsl).
struct StructuredGridInfo {
    vec4 mapOrigin;  // xyz: first texel of the grid's inverse map in the atlas; w: 1 when structured
    vec4 mapScale;   // xyz: inverse-map texels per lattice voxel; w: world step of gradient differences
};

// A colour node of a lit-sphere style track (styles.glsl).
struct StyleNode {
    vec4 tintAndPosition;  // rgb: tint (a flat node's colour), a: position on the track
    ivec4 layer;           // x: layer in the style array, -1 for a flat colour
};
