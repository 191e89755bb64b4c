// Binding points shared by the C++ side (render/bindings.h) and every shader.
const int ATLAS_UNIT = 0;
const int MASK_ATLAS_UNIT = 1;
const int ENTRY_EXIT_UNIT = 2;
const int STF_UNIT = 4;
const int GRADIENT_TSTF_UNIT = 5;
const int STYLE_UNIT = 6;
const int OCCUPANCY_UNIT = 7;
const int INVERSE_MAP_UNIT = 8;
const int PACKED_ATLAS_UNIT = 9;
const int PACKED_OCCUPANCY_UNIT = 10;
const int PACKED_VALIDITY_UNIT = 11;

#define TIME_STEP_BUFFER 0
#define PROXY_BUFFER 1
#define INDEX_TSTF_BUFFER 2
#define STATISTICS_BUFFER 3
#define STYLE_NODE_BUFFER 4
#define STRUCTURED_GRID_BUFFER 5
#define PROXY_MESH_BUFFER 6
#define UNEVEN_AXIS_BUFFER 7
#define AXIS_NODE_BUFFER 8
#define BEAM_ANGLE_BUFFER 9
#define PACKED_GROUP_BUFFER 10

// Entry buffers are cleared to NO_ENTRY and exit buffers to NO_EXIT; a pixel whose ray misses a
// proxy keeps them.
const float NO_ENTRY = 1.0e30;
const float NO_EXIT = -1.0e30;
