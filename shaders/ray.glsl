// The viewing ray of a pixel. Entry/exit depths and the ray iteration both measure the ray
// parameter t from the point where the ray crosses the near plane, so they agree exactly.
uniform mat4 inverseViewProjection;
uniform vec2 viewportSize;

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
