// Proxy geometry for the entry/exit buffers: one box per distinct time-step placement of a
// rectilinear grid (time-steps that share grid and placement share a box and a layer). Beam grids
// have a mesh instead (proxy_mesh.glsl).
#include "contract.glsl"

layout(std430, binding = PROXY_BUFFER) readonly buffer ProxyBoxes {
    ProxyBox boxes[];
} proxy;
