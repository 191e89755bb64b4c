// Volume overlap extraction (paper 5.1): per pixel, read every time-step's entry and exit depth,
// keep the time-steps the ray meets (sorted by entry depth) and the ray depth, the minimum entry
// and maximum exit over all of them.
// Per time-step layer: entry depth in red, the negated exit depth in green (entry_exit.frag).
#include "contract.glsl"
#include "variant_switches.glsl"
#include "time_steps.glsl"
layout(binding = ENTRY_EXIT_UNIT) uniform sampler2DArray entryExitDepths;
#include "raycast_uniforms.glsl"


// The time-steps this ray meets, in order of entry, with their own [entry, exit] interval.
int activeCount;
int activeSteps[MAX_TIME_STEPS];
vec2 activeIntervals[MAX_TIME_STEPS];


// Returns the ray depth (min entry, max exit); empty (x >= y) when the ray meets no time-step.
vec2 extractVolumeOverlap(ivec2 pixel) {
    activeCount = 0;
    vec2 rayDepth = vec2(NO_ENTRY, NO_EXIT);
#if PACKED_ALIGNED
    // Every time-step has the same proxy, hence the same interval: one list entry, the first (or
    // the first exposed) time-step's, stands for all of them.
    int firstStep = exposedSteps.x;
    int lastStep = firstStep + 1;
#else
    int firstStep = 0;
    int lastStep = timeStepCount;
#endif
    for (int step = firstStep; step < lastStep; ++step) {
        if (step < exposedSteps.x || step > exposedSteps.y) continue;
        int layer = timeSteps.steps[step].layer.x;
        vec2 depths = texelFetch(entryExitDepths, ivec3(pixel, layer), 0).rg;
        float exitDepth = -depths.y;
        if (exitDepth <= 0.0) continue;  // missed, or the whole box lies behind the near plane
        float entryDepth = depths.x;
        // No entry face but an exit: the near plane cuts the box, the ray starts inside it.
        if (entryDepth >= NO_ENTRY) entryDepth = 0.0;
        entryDepth = max(entryDepth, 0.0);
        if (exitDepth <= entryDepth) continue;

        // Insertion by entry depth keeps the list in the order the ray meets the time-steps.
        int slot = activeCount;
        while (slot > 0 && activeIntervals[slot - 1].x > entryDepth) {
            activeSteps[slot] = activeSteps[slot - 1];
            activeIntervals[slot] = activeIntervals[slot - 1];
            --slot;
        }
        activeSteps[slot] = step;
        activeIntervals[slot] = vec2(entryDepth, exitDepth);
        ++activeCount;
        rayDepth = vec2(min(rayDepth.x, entryDepth), max(rayDepth.y, exitDepth));
    }
    return rayDepth;
}

// The slots of the list that can contain the current sample: [liveBegin, liveEnd). Slots before
// liveBegin were left behind, slots from liveEnd on are not reached yet; the ray's samples move
// forward only, so both ends only grow. Per sample this costs a step or two instead of a pass over
// the whole list (which llvmpipe pays for the longest list of 8 pixels at a time).
int liveBegin = 0;
int liveEnd = 0;

void advanceLiveWindow(float t) {
    while (liveEnd < activeCount && activeIntervals[liveEnd].x <= t) ++liveEnd;
    while (liveBegin < liveEnd && activeIntervals[liveBegin].y < t) ++liveBegin;
}

// The first entry depth after t (the last position given to advanceLiveWindow) among the active
// time-steps, or `limit` if there is none: where the next time-step begins when the ray is in empty
// space between boxes. The list is in entry order, so that is the first slot not reached yet.
float nextEntryAfter(float t, float limit) {
    return liveEnd < activeCount ? min(activeIntervals[liveEnd].x, limit) : limit;
}
