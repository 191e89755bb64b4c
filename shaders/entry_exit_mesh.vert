#version 450 core
// Entry/exit buffer generation, step 1 for proxy meshes (beam fans, the boundary faces of
// structured grids): vertex gl_VertexID of the mesh of every such grid, drawn in one call; the
// geometry and fragment stages are the boxes'.
#include "contract.glsl"
#include "proxy_mesh.glsl"

uniform mat4 viewProjection;

out VertexData {
    vec3 worldPosition;
    vec3 worldNormal;
    flat int layer;
} vertexOut;

void main() {
    ProxyVertex vertex = proxyMesh.vertices[gl_VertexID];
    vertexOut.worldPosition = vertex.position.xyz;
    vertexOut.worldNormal = vertex.normal.xyz;
    vertexOut.layer = int(vertex.position.w);
    gl_Position = viewProjection * vec4(vertex.position.xyz, 1.0);
}
