// The viewing ray of a pixel. Entry/exit depths and the ray iteration both measure the ray
// parameter t from the point where the ray crosses the near plane, so they agree exactly.
#include "raycast_uniforms.glsl"

struct Ray {
    vec3 origin;     // on the near plane
    vec3 direction;  // unit length
};

Ray rayForPixel(vec2 fragCoord) {
    vec2 ndc = fragCoord / viewportSize * 2.0 - 1.0;
    vec4 nearPoint = inverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec4 farPoint = inverseViewProjection * vec4(ndc, 1.0, 1.0);
    Ray ray;
    ray.origin = nearPoint.xyz / nearPoint.w;
    ray.direction = normalize(farPoint.xyz / farPoint.w - ray.origin);
    return ray;
}

// The part [near, far] of the ray inside the axis-aligned world box [lower, upper], in the same ray
// parameter; empty (near >= far) where the ray misses it. An axis the ray runs parallel to gets a
// tiny direction instead of zero, so that a ray on a face plane gives no NaN.
vec2 rayBoxInterval(Ray ray, vec3 lower, vec3 upper) {
    vec3 direction = mix(ray.direction, vec3(1e-30), equal(ray.direction, vec3(0.0)));
    vec3 toLower = (lower - ray.origin) / direction;
    vec3 toUpper = (upper - ray.origin) / direction;
    vec3 nearest = min(toLower, toUpper);
    vec3 farthest = max(toLower, toUpper);
    return vec2(max(max(nearest.x, nearest.y), nearest.z), min(min(farthest.x, farthest.y), farthest.z));
}
