// Proxy meshes for the entry/exit buffers of grids that are not boxes (beam fans, structured
// grids' boundary faces): world-space
// triangles, three vertices each, with the triangle's outward normal and its layer.
#include "contract.glsl"

layout(std430, binding = PROXY_MESH_BUFFER) readonly buffer ProxyMesh {
    ProxyVertex vertices[];
} proxyMesh;
