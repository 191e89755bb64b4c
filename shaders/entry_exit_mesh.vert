#version 450 core
// Entry/exit buffer generation, step 1 for structured grids: the vertices of the grids' boundary
// faces, pulled from the mesh buffer by gl_VertexID (world positions, each with its layer).
#include "bindings.glsl"

struct BoundaryVertex {
    vec4 positionLayer;  // xyz: world position; w: entry/exit layer
    vec4 normal;         // xyz: world normal, pointing out of the grid
};

layout(std430, binding = BOUNDARY_MESH_BUFFER) readonly buffer BoundaryMesh {
    BoundaryVertex vertices[];
} boundary;

uniform mat4 viewProjection;

out VertexData {
    vec3 worldPosition;
    vec3 worldNormal;
    flat int layer;
} vertexOut;

void main() {
    BoundaryVertex vertex = boundary.vertices[gl_VertexID];
    vertexOut.worldPosition = vertex.positionLayer.xyz;
    vertexOut.worldNormal = vertex.normal.xyz;
    vertexOut.layer = int(vertex.positionLayer.w + 0.5);
    gl_Position = viewProjection * vec4(vertex.positionLayer.xyz, 1.0);
}
