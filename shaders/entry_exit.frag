#version 450 core
// Entry/exit buffer generation, step 3: each fragment writes its ray parameter t. Faces turned to
// the viewer are entries, the others exits; MIN blending on the entry target and MAX blending on
// the exit target keep the nearest entry and the farthest exit of each box.
#include "bindings.glsl"
#include "ray.glsl"

in FragmentData {
    vec3 worldPosition;
    vec3 worldNormal;
} fragmentIn;

layout(location = 0) out float entryDepth;
layout(location = 1) out float exitDepth;

void main() {
    Ray ray = rayForPixel(gl_FragCoord.xy);
    float t = dot(fragmentIn.worldPosition - ray.origin, ray.direction);
    bool facesViewer = dot(fragmentIn.worldNormal, ray.direction) < 0.0;
    entryDepth = facesViewer ? t : NO_ENTRY;
    exitDepth = facesViewer ? NO_EXIT : t;
}
