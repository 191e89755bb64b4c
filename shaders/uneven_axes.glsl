// Uneven rectilinear axes (depth or pressure levels): along such an axis the time-step's
// worldToVoxel gives the grid-local position, and the axis' node list turns it into a fractional
// node index (bucket lookup, then linear between the two nodes). Mirrors tstyles/data/grid_axes.h.
#include "contract.glsl"
#include "variant_switches.glsl"
layout(std430, binding = UNEVEN_AXIS_BUFFER) readonly buffer UnevenAxes {
    ivec4 firstNode[];  // per time-step, per axis: index of its first node in axisNodes; -1: even
} unevenAxes;
layout(std430, binding = AXIS_NODE_BUFFER) readonly buffer AxisNodes {
    float positions[];  // the nodes of every uneven axis, each list increasing from 0
} axisNodes;

// 0 when no time-step of the series has an uneven axis: the node lookups are then left out of the
// program. llvmpipe runs their loops, masked, wherever voxelCoordinate() is reached (beam grids
// too), and every such pass counts against its limit of 65535 loop passes per invocation, which
// bounds the samples a ray can take (docs/architecture.md, "Limits: samples per ray on llvmpipe").

bool isUnevenAxis(int step, int axis) {
#if !UNEVEN_AXES
    return false;
#else
    return unevenAxes.firstNode[step][axis] >= 0;
#endif
}

// The fractional node index of grid-local `position` along an uneven axis; clamped to the grid.
// Mirrors lookUpNodeIndex (tstyles/render/uneven_axis_table.h).
float nodeIndexOf(int step, int axis, float position) {
    int first = unevenAxes.firstNode[step][axis];
    int count = int(timeSteps.steps[step].dims[axis]);
    // After the nodes, a bucket lookup: 1 / bucket width, bucket count, each bucket's lower node.
    int lookup = first + count;
    int buckets = int(axisNodes.positions[lookup + 1]);
    int bucket = clamp(int(position * axisNodes.positions[lookup]), 0, buckets - 1);
    // The last node at or below `position`, in [0, count - 2].
    int low = int(axisNodes.positions[lookup + 2 + bucket]);
#if UNEVEN_AXIS_WALK
    // Some axis' buckets are wider than half its finest gap (the table's limit): walk.
    while (low < count - 2 && axisNodes.positions[first + low + 1] <= position) ++low;
    while (low > 0 && axisNodes.positions[first + low] > position) --low;
#else
    // Buckets at most half the finest gap wide: the node is the bucket's or the next one (the one
    // before where float rounding picked the next bucket). No loop: llvmpipe counts a pass of a
    // while loop even where it runs none, and these ran for every time-step at every sample (twice
    // with empty-space skipping), which cut the hurricane's rays short on the general path.
    if (low < count - 2 && axisNodes.positions[first + low + 1] <= position) ++low;
    if (low > 0 && axisNodes.positions[first + low] > position) --low;
#endif
    float lower = axisNodes.positions[first + low];
    float upper = axisNodes.positions[first + low + 1];
    return clamp(float(low) + (position - lower) / (upper - lower), 0.0, float(count - 1));
}

// The grid-local position of a fractional node index along an uneven axis.
float nodePositionOf(int step, int axis, float index) {
    int first = unevenAxes.firstNode[step][axis];
    int cell = clamp(int(floor(index)), 0, int(timeSteps.steps[step].dims[axis]) - 2);
    float lower = axisNodes.positions[first + cell];
    float upper = axisNodes.positions[first + cell + 1];
    return mix(lower, upper, index - float(cell));
}

// worldToVoxel's result -> voxel coordinates: even axes are already node indices.
vec3 applyUnevenAxes(int step, vec3 gridCoordinate) {
    vec3 voxel = gridCoordinate;
#if UNEVEN_AXES
    for (int axis = 0; axis < 3; ++axis)
        if (isUnevenAxis(step, axis)) voxel[axis] = nodeIndexOf(step, axis, gridCoordinate[axis]);
#endif
    return voxel;
}

// Voxel coordinates -> the space worldToVoxel maps into (grid-local along uneven axes), where a
// ray is a straight line with the same parameter t.
vec3 unapplyUnevenAxes(int step, vec3 voxel) {
    vec3 gridCoordinate = voxel;
#if UNEVEN_AXES
    for (int axis = 0; axis < 3; ++axis)
        if (isUnevenAxis(step, axis)) gridCoordinate[axis] = nodePositionOf(step, axis, voxel[axis]);
#endif
    return gridCoordinate;
}

// Whole node indices -> grid-local positions (a brick's faces): one read per uneven axis, none
// along even ones.
void nodeBoundsToGrid(int step, inout vec3 lower, inout vec3 upper) {
#if UNEVEN_AXES
    ivec4 firstNode = unevenAxes.firstNode[step];
    for (int axis = 0; axis < 3; ++axis) {
        if (firstNode[axis] < 0) continue;
        lower[axis] = axisNodes.positions[firstNode[axis] + int(lower[axis])];
        upper[axis] = axisNodes.positions[firstNode[axis] + int(upper[axis])];
    }
#endif
}

// The largest coordinate worldToVoxel gives inside the grid: dims - 1, or the last node's position.
vec3 gridCoordinateLimit(int step) {
    return unapplyUnevenAxes(step, timeSteps.steps[step].dims.xyz - 1.0);
}
