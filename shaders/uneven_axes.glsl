// Uneven rectilinear axes (depth or pressure levels): along such an axis the time-step's
// worldToVoxel gives the grid-local position, and the axis' node list turns it into a fractional
// node index (the record of the position's bucket, render/uneven_axis_table.h). Mirrors
// tstyles/data/grid_axes.h.
#include "contract.glsl"
#include "variant_switches.glsl"
#include "uneven_axis_nodes.glsl"
#if UNEVEN_AXES
// Per bucket of each axis: the first node after the bucket's start (x), its index (y), and the node
// indices per grid-local unit below (z) and above (w) it (UnevenAxisTable::cells). A texel fetch:
// llvmpipe reads the four at once, where four reads of a storage buffer are four gathers.
layout(binding = UNEVEN_CELL_UNIT) uniform samplerBuffer unevenCells;
#endif

// 0 when no time-step of the series has an uneven axis: the node lookups are then left out of the
// program. llvmpipe runs their loops, masked, wherever voxelCoordinate() is reached (beam grids
// too), and every such pass counts against its limit of 65535 loop passes per invocation, which
// bounds the samples a ray can take (docs/architecture.md, "Limits: samples per ray on llvmpipe").

bool isUnevenAxis(int step, int axis) {
#if !UNEVEN_AXES
    return false;
#else
    return hasUnevenAxisNodes(step, axis);
#endif
}

#if UNEVEN_AXES
// The fractional node index of grid-local `position` along uneven axis `axis` of a grid with these
// lookup numbers (`info`, read once per ray where the grid stays the same) and `count` nodes along
// it; clamped to the grid. Mirrors lookUpNodeIndex (tstyles/render/uneven_axis_table.h).
float nodeIndexIn(UnevenAxisInfo info, int axis, int count, float position) {
    int bucket = clamp(int(position * info.bucketsPerUnit[axis]), 0, info.bucketCount[axis] - 1);
    vec4 cell = texelFetch(unevenCells, info.firstCell[axis] + bucket);
#if UNEVEN_AXIS_WALK
    // Some axis' buckets are wider than half its finest gap (the table's limit): walk from the cell
    // the bucket starts in. llvmpipe counts a pass of a while loop even where it runs none, and
    // these run for every time-step at every sample, so only such axes have them.
    int first = info.firstNode[axis];
    int low = int(cell.y) - 1;
    while (low < count - 2 && axisNodes.positions[first + low + 1] <= position) ++low;
    while (low > 0 && axisNodes.positions[first + low] > position) --low;
    float lower = axisNodes.positions[first + low];
    float upper = axisNodes.positions[first + low + 1];
    return clamp(float(low) + (position - lower) / (upper - lower), 0.0, float(count - 1));
#else
    // The bucket holds at most one node, cell.x: linear on either side of it. (Where float rounding
    // picked the next bucket, the position lies within rounding of its start, and the cell below
    // cell.x gives the same index.)
    float index = cell.y + (position - cell.x) * (position < cell.x ? cell.z : cell.w);
    return clamp(index, 0.0, float(count - 1));
#endif
}

// The node index along every uneven axis of such a grid; `nodes`: its node counts.
vec3 applyUnevenAxesIn(UnevenAxisInfo info, ivec3 nodes, vec3 gridCoordinate) {
    vec3 voxel = gridCoordinate;
    for (int axis = 0; axis < 3; ++axis)
        if (info.firstNode[axis] >= 0) voxel[axis] = nodeIndexIn(info, axis, nodes[axis], gridCoordinate[axis]);
    return voxel;
}
#endif

// worldToVoxel's result -> voxel coordinates: even axes are already node indices.
vec3 applyUnevenAxes(int step, vec3 gridCoordinate) {
#if UNEVEN_AXES
    return applyUnevenAxesIn(unevenAxes.steps[step], ivec3(timeSteps.steps[step].dims.xyz), gridCoordinate);
#else
    return gridCoordinate;
#endif
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
    ivec4 firstNode = unevenAxes.steps[step].firstNode;
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
