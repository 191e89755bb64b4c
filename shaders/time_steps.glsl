// The per-time-step table (TimeStepInfo, contract.glsl): where each time-step's samples are in the
// world and where its brick is in the atlas.
#include "contract.glsl"

layout(std430, binding = TIME_STEP_BUFFER) readonly buffer TimeSteps {
    TimeStepInfo steps[];
} timeSteps;
