// The node lists of uneven rectilinear axes (render/uneven_axis_table.h) and the grid-local
// position of a node index: what the raycaster (uneven_axes.glsl) and the gradient atlas'
// computation (gradient_atlas.comp) both read. No switches: any program may include it.
#include "contract.glsl"
#include "time_steps.glsl"

layout(std430, binding = UNEVEN_AXIS_BUFFER) readonly buffer UnevenAxes {
    UnevenAxisInfo steps[];  // per time-step
} unevenAxes;
layout(std430, binding = AXIS_NODE_BUFFER) readonly buffer AxisNodes {
    float positions[];  // the nodes of every uneven axis, each list increasing from 0
} axisNodes;

// Whether the time-step's axis (0, 1, 2: x, y, z) is uneven, read from the table.
bool hasUnevenAxisNodes(int step, int axis) {
    return unevenAxes.steps[step].firstNode[axis] >= 0;
}

// The grid-local position of a fractional node index along an uneven axis.
float nodePositionOf(int step, int axis, float index) {
    int first = unevenAxes.steps[step].firstNode[axis];
    int cell = clamp(int(floor(index)), 0, int(timeSteps.steps[step].dims[axis]) - 2);
    float lower = axisNodes.positions[first + cell];
    float upper = axisNodes.positions[first + cell + 1];
    return mix(lower, upper, index - float(cell));
}
