// Proxy meshes for the entry/exit buffers of grids that are not boxes (beam fans, structured
// grids' boundary faces): world-space
// triangles, three vertices each, with the triangle's outward normal and its layer.
struct ProxyVertex {
    vec4 position;  // xyz: world position; w: layer in the entry/exit buffers
    vec4 normal;    // xyz: the triangle's outward normal in world space
};

layout(std430, binding = PROXY_MESH_BUFFER) readonly buffer ProxyMesh {
    ProxyVertex vertices[];
} proxyMesh;
