#version 450 core
// Entry/exit buffer generation, step 3: each fragment writes its ray parameter t. Faces turned to
// the viewer are entries (red), the others exits (green, negated); MIN blending keeps the nearest
// entry and the farthest exit of each proxy.
#include "contract.glsl"
#include "ray.glsl"

in FragmentData {
    vec3 worldPosition;
    vec3 worldNormal;
} fragmentIn;

layout(location = 0) out vec2 entryAndNegatedExit;

void main() {
    Ray ray = rayForPixel(gl_FragCoord.xy);
    float t = dot(fragmentIn.worldPosition - ray.origin, ray.direction);
    bool facesViewer = dot(fragmentIn.worldNormal, ray.direction) < 0.0;
    entryAndNegatedExit = facesViewer ? vec2(t, -NO_EXIT) : vec2(NO_ENTRY, -t);
}
