#version 450 core
// Entry/exit buffer generation, step 2: route each box's triangles to its own layer, so that all
// boxes are drawn in one call however many time-steps there are.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in VertexData {
    vec3 worldPosition;
    vec3 worldNormal;
    flat int layer;
} vertexIn[];

out FragmentData {
    vec3 worldPosition;
    vec3 worldNormal;
} vertexOut;

void main() {
    for (int i = 0; i < 3; ++i) {
        gl_Layer = vertexIn[i].layer;
        gl_Position = gl_in[i].gl_Position;
        vertexOut.worldPosition = vertexIn[i].worldPosition;
        vertexOut.worldNormal = vertexIn[i].worldNormal;
        EmitVertex();
    }
    EndPrimitive();
}
