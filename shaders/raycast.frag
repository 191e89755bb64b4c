#version 450 core
// Ray iteration (paper 5.2): march the ray depth in fixed world-space steps, ask the temporal
// compositor for a temporal characteristic at each sample, and hand the samples, front to back, to
// the ray mode, which makes the pixel of them (composite: front to back with opacity correction for
// the step length, stopping early once the ray is nearly opaque; or a maximum, an average, an
// iso-surface, ...: ray_sample.glsl).
// This is the template of every raycasting program: RaycastVariant (src/render/raycast_variant.cpp)
// picks the modules that "compositor.glsl", "time_step_walk.glsl" and "ray_mode.glsl" stand for and
// the switches.
#include "contract.glsl"
#include "variant_switches.glsl"
#include "raycast_uniforms.glsl"
#include "ray.glsl"
#include "overlap_extraction.glsl"
#include "temporal_compositor.glsl"
#include "ray_mode.glsl"


// The first lattice point after t; a segment shorter than 1 % of a step joins the next one (float
// rounding must never make an empty segment).
float nextLatticePoint(float t, float anchor) {
    float point = anchor + (floor((t - anchor) / stepLength) + 1.0) * stepLength;
    return point <= t + 0.01 * stepLength ? point + stepLength : point;
}

float latticePointAtOrBefore(float t, float anchor) {
    return anchor + floor((t - anchor) / stepLength) * stepLength;
}

// 64-bit counters as (low, high) pairs (GLSL 4.50 has only 32-bit atomics), filled with
// COLLECT_STATISTICS; `cutShortRays` always.
layout(std430, binding = STATISTICS_BUFFER) buffer Statistics {
    uvec2 rays;
    uvec2 samples;
    uvec2 fetches;
    uint cutShortRays;
} statistics;

#if COLLECT_STATISTICS

// A macro, not a function: atomics need the buffer variable itself, not a copy.
#define ADD_TO_COUNTER(counter, amount)                           \
    {                                                             \
        uint before = atomicAdd(counter.x, amount);               \
        if (before + (amount) < before) atomicAdd(counter.y, 1u); \
    }
#endif

layout(location = 0) out vec4 fragmentColor;  // premultiplied by alpha

void main() {
    Ray ray = rayForPixel(gl_FragCoord.xy);
    vec2 rayDepth = extractVolumeOverlap(ivec2(gl_FragCoord.xy));
    vec2 clip = rayBoxInterval(ray, clipLower, clipUpper);
    // A ray that meets no time-step (in the clip box) would give the background, which the renderer
    // has already cleared the target to. Discarding it lets llvmpipe skip the rest of the shader for
    // a block of pixels that all miss (a branch would not: both sides run, masked).
    if (max(rayDepth.x, clip.x) >= min(rayDepth.y, clip.y)) discard;
    prepareWalk(ray);
    if (RAYCAST_PART == RAYCAST_PART_RAY_SETUP) {
        // The ray's setup alone (`bench --stages`): what the walk has in reach at the entry goes
        // into an opacity far too small to show, so that the compiler keeps the setup.
        advanceWalk(rayDepth.x);
        fragmentColor = vec4(0.0, 0.0, 0.0, 1.0e-30 * float(timeStepsInReach()));
        return;
    }

    RayState rayState = rayInit(ray);
    int samples = 0;
    int fetches = 0;
    float anchor = max(rayBoxInterval(ray, seriesLower, seriesUpper).x, 0.0);
    // In a block, start at the segment that holds the clip's entry.
    float t = clip.x > rayDepth.x ? max(rayDepth.x, latticePointAtOrBefore(clip.x, anchor)) : rayDepth.x;
    while (t < rayDepth.y && !rayDone(rayState)) {
        // Each sample stands for the segment [t, segmentEnd], from t to the next lattice point; the
        // first (at the ray's entry, or after a jump) and the last (at the exit) are shorter, so a
        // slab of thickness D gets exactly D worth of opacity.
        float segmentEnd = min(nextLatticePoint(t, anchor), rayDepth.y);
        float middle = 0.5 * (t + segmentEnd);
        if (middle < clip.x) {  // the block in front's segment
            t = segmentEnd;
            continue;
        }
        if (middle >= clip.y) {  // the block behind's: this block's part of the ray is done
            t = rayDepth.y;
            break;
        }
        advanceWalk(middle);
        vec3 position = ray.origin + ray.direction * middle;
#if SKIP_UNCHANGING_BRICKS
        float changeFloor = rayChangeFloor(rayState);
#else
        float changeFloor = -1.0;
#endif
        TemporalSample sampled = compositeTemporal(position, middle, changeFloor);
        samples += 1;
        fetches += sampled.fetches;
#if SKIP_UNCHANGING_BRICKS
        if (sampled.unchangingUntil > 0.0) {
            // No place in the brick changes enough to replace the sample the ray keeps. Go on from
            // the last lattice point before the brick's end, so that the ray takes the very samples
            // it would have taken without the jump: the same picture.
            t = max(segmentEnd, latticePointAtOrBefore(min(sampled.unchangingUntil, rayDepth.y), anchor));
            continue;
        }
#endif
        if (WALK_SKIPS_EMPTY_SPACE && sampled.contributing == 0) {
            // Between time-steps: jump to where the next one begins.
            t = nextEntryAfter(middle, rayDepth.y);
            rayPassGap(rayState);
            continue;
        }
        if (WALK_SKIPS_EMPTY_SPACE && sampled.emptyUntil > 0.0) {
            // Every time-step here is transparent: jump to the end of the empty bricks, but not past
            // the entry of a time-step the ray has not reached yet.
            float next = max(segmentEnd, min(sampled.emptyUntil, nextEntryAfter(middle, rayDepth.y)));
            rayPassEmpty(rayState, next - t);
            t = next;
            continue;
        }
        rayAccumulate(rayState, RaySample(sampled.characteristic, position, middle, segmentEnd - t), fetches);
        t = segmentEnd;
    }

    // The loop ends only at the exit or where the ray mode is done. A ray that stopped before both
    // was cut short by the driver: llvmpipe ends every loop of an invocation once 65535 loop passes
    // have run in it (docs/architecture.md, "Limits: samples per ray on llvmpipe"). Counted, so
    // that the front end can say that the image is incomplete.
    if (t < rayDepth.y && !rayDone(rayState)) atomicAdd(statistics.cutShortRays, 1u);
    vec4 accumulated = rayFinish(rayState, fetches);

#if COLLECT_STATISTICS
    if (rayDepth.x < rayDepth.y) {
        ADD_TO_COUNTER(statistics.rays, 1u)
        ADD_TO_COUNTER(statistics.samples, uint(samples))
        ADD_TO_COUNTER(statistics.fetches, uint(fetches))
    }
#endif
    vec4 premultipliedBackground = vec4(background.rgb * background.a, background.a);
    fragmentColor = accumulated + (1.0 - accumulated.a) * premultipliedBackground;
    // The march alone: its samples' time-steps in reach (TemporalSample.fetches) go into an opacity
    // far too small to show, so that the compiler keeps the walk.
    if (RAYCAST_PART == RAYCAST_PART_MARCH) fragmentColor.a += 1.0e-30 * float(fetches);
}
