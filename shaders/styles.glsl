// Lit-sphere styles (style transfer functions, Bruckner and Groeller 2007): a sample's colour is read
// from a lit-sphere image at its view-space normal, and the style's alpha multiplies the opacity.
// Each transfer function ("track") has its colour nodes in a table; between two nodes the colour is
// the blend of their two lookups. A flat colour node is a style of one colour.
#include "contract.glsl"
#include "variant_switches.glsl"
layout(binding = STYLE_UNIT) uniform sampler2DArray styles;

layout(std430, binding = STYLE_NODE_BUFFER) readonly buffer StyleNodes {
    StyleNode nodes[];
} styleNodes;

const int STF_TRACK = 0;
const int INDEX_TSTF_TRACK = 1;
const int GRADIENT_TSTF_TRACK = 2;

#include "raycast_uniforms.glsl"

struct SphereCoordinate {
    vec2 uv;
};

// Where a sample reads the lit sphere: its view-space normal (the negated density gradient, turned
// to face the viewer), or the sphere's centre where the gradient is too small to give a normal.
SphereCoordinate sphereCoordinate(vec3 gradient) {
    float magnitude = length(gradient);
    if (magnitude < 1.0e-4) return SphereCoordinate(vec2(0.5));
    vec3 normal = worldToView * (-gradient / magnitude);
    if (normal.z < 0.0) normal = -normal;
    // Row 0 of a style image is its top (normal.y = +1) and is uploaded at t = 0.
    return SphereCoordinate(vec2(0.5 + 0.5 * normal.x, 0.5 - 0.5 * normal.y));
}

// Premultiplied colour of one node at a sphere coordinate.
vec4 nodeLook(int node, SphereCoordinate sphere) {
    vec3 tint = styleNodes.nodes[node].tintAndPosition.rgb;
    int layer = styleNodes.nodes[node].layer.x;
    if (layer < 0) return vec4(tint, 1.0);
    vec4 look = textureGrad(styles, vec3(sphere.uv, float(layer)), vec2(styleFootprint, 0.0),
                            vec2(0.0, styleFootprint));
    return vec4(look.rgb * tint, look.a);
}

float nodePosition(int node) {
    return styleNodes.nodes[node].tintAndPosition.a;
}

// The styled colour of a track at x: rgb (not premultiplied) and the style's alpha. Below the first
// node the weight is 0 and above the last it is 1, so one pair of lookups serves every x (with a
// branch per case llvmpipe would run every case's lookups, masked).
vec4 trackStyle(int track, float x, SphereCoordinate sphere) {
    int first = styleTracks[track].x;
    // One node: its lookup is the colour everywhere (SINGLE_NODE_STYLE_TRACKS; `track` is a
    // constant at every call, so this is decided when the program is compiled). The blend below
    // would mix that lookup with itself at twice the cost: the lit sphere is a mipmapped lookup.
    if ((SINGLE_NODE_STYLE_TRACKS & (1 << track)) != 0) {
        vec4 look = nodeLook(first, sphere);
        return vec4(look.a > 0.0 ? look.rgb / look.a : vec3(0.0), look.a);
    }
    int last = first + styleTracks[track].y - 1;
    int node = first;
    while (node < last - 1 && x >= nodePosition(node + 1)) ++node;
    int next = min(node + 1, last);
    float span = nodePosition(next) - nodePosition(node);
    float weight = span > 0.0 ? clamp((x - nodePosition(node)) / span, 0.0, 1.0) : 0.0;
    vec4 look = mix(nodeLook(node, sphere), nodeLook(next, sphere), weight);
    return vec4(look.a > 0.0 ? look.rgb / look.a : vec3(0.0), look.a);
}

// Whether a track has styles (STYLED_TRACKS), known when the program is compiled.
bool isStyledTrack(int track) {
    return (STYLED_TRACKS & (1 << track)) != 0;
}

// A classification (colour, opacity) with its track's style applied, if the track has styles.
vec4 applyStyle(int track, float x, vec4 classification, SphereCoordinate sphere) {
#if !STYLED
    // Flat scenes: no style code in the program at all (llvmpipe would run it, masked, anyway).
    return classification;
#endif
    // A track without styles has no style code in the program: `track` is a constant at every
    // call, so this test is decided when the program is compiled.
    if (!isStyledTrack(track)) return classification;
    vec4 styled = trackStyle(track, x, sphere);
    return vec4(styled.rgb, classification.a * styled.a);
}
