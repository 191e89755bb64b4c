#version 450 core
// Entry/exit buffer generation, step 1: the 36 vertices of proxy box gl_InstanceID, made from
// gl_VertexID (no vertex buffer needed).
#include "contract.glsl"
#include "proxy_geometry.glsl"

uniform mat4 viewProjection;

out VertexData {
    vec3 worldPosition;
    vec3 worldNormal;
    flat int layer;
} vertexOut;

// Faces in the order -x, +x, -y, +y, -z, +z; two triangles each.
const ivec3 faceAxes[6] = ivec3[6](ivec3(0, 1, 2), ivec3(0, 1, 2), ivec3(1, 2, 0), ivec3(1, 2, 0),
                                   ivec3(2, 0, 1), ivec3(2, 0, 1));
const vec2 quadCorners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));

void main() {
    int face = gl_VertexID / 6;
    int axis = faceAxes[face].x;
    float side = float(face % 2);
    vec2 corner = quadCorners[gl_VertexID % 6];
    vec3 local = vec3(0.0);
    local[axis] = side;
    local[faceAxes[face].y] = corner.x;
    local[faceAxes[face].z] = corner.y;
    vec3 normal = vec3(0.0);
    normal[axis] = side * 2.0 - 1.0;

    ProxyBox box = proxy.boxes[gl_InstanceID];
    vec4 world = box.gridToWorld * vec4(local * box.extent.xyz, 1.0);
    vertexOut.worldPosition = world.xyz;
    vertexOut.worldNormal = mat3(box.gridToWorld) * normal;
    vertexOut.layer = int(box.extent.w);
    gl_Position = viewProjection * world;
}
