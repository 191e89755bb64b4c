// The walk over the time-steps of a fully aligned series (packed_time_steps.glsl): every time-step
// contains every sample of the ray (they share one interval), read in groups of four with one fetch
// per group, with one occupancy test for all of them and, with PACKED_GROUP_MASKS, only the groups
// visible in the sample's brick for compositors that leave transparent time-steps out, and for the
// others the groups outside it without STF lookups. Packed series are rectilinear and have no
// masks, so every sample in the interval is in every grid.
#include "variant_switches.glsl"
#include "ray.glsl"
#include "overlap_extraction.glsl"
#include "voxel_rays.glsl"
#include "packed_time_steps.glsl"
#include "time_step_visit.glsl"

const bool WALK_SKIPS_EMPTY_SPACE = true;

struct SamplePoint {
    vec3 position;  // in the world
    float t;        // on the ray
    AlignedSample aligned;
};

void prepareWalk(Ray ray) {
    prepareVoxelRays(ray);
    prepareAlignedSamples();
}

void advanceWalk(float t) {
    advanceLiveWindow(t);
}

// How many time-steps the walk has in reach at its last sample (the slots of the live window): what the
// parts of the pass that `bench --stages` times keep of the walk (RAYCAST_PART).
int timeStepsInReach() {
    return liveEnd - liveBegin;
}

// Time-steps in a group: four, but fewer in the last. A loop bound that is the same for every
// pixel ends there, where a test in the loop would still run the missing lanes (llvmpipe runs a
// loop pass that every pixel skips, masked).
int lanesOfGroup(int group) {
    return min(4, timeStepCount - 4 * group);
}

SamplePoint samplePointAt(vec3 position, float t) {
    return SamplePoint(position, t, alignedSampleAt(t));
}

float emptySpaceUntil(SamplePoint point) {
    return packedEmptySpaceUntil(point.aligned, point.t);
}

#if SKIP_UNCHANGING_BRICKS
// Whether the sample's brick may change by more than `changeFloor` over time: -1 if so, else where
// the brick ends.
float unchangingSpaceUntil(SamplePoint point, float changeFloor) {
    return packedUnchangingSpaceUntil(point.aligned, point.t, changeFloor);
}
#endif

// One group of four time-steps at the sample: one fetch, then each exposed time-step to the
// compositor. `knownTransparent` (a constant at every call, so only one kind of visit is in the
// program there): the brick's group mask lacks the group, every time-step of it is transparent, and
// the compositor needs their densities but not their STF colours, so they skip the STF lookup.
void visitGroup(inout CompositorState state, SamplePoint point, int group, bool knownTransparent, float sharedValidity,
                inout TemporalSample result) {
    vec4 groupDensities = packedDensities(group, point.aligned.voxel, sharedValidity);
    result.fetches += PACKED_FETCHES_PER_GROUP;
    int lanes = lanesOfGroup(group);
    // All four transparent under the STF (or without data): nothing for a compositor that leaves
    // transparent time-steps out. They still count as met, so the ray does not jump.
    if (COMPOSITOR_IGNORES_TRANSPARENT && !stfMayBeVisible(groupDensities.x) && !stfMayBeVisible(groupDensities.y) &&
        !stfMayBeVisible(groupDensities.z) && !stfMayBeVisible(groupDensities.w)) {
        result.contributing += lanes;
        return;
    }
    for (int lane = 0; lane < lanes; ++lane) {
        int step = 4 * group + lane;
        if (step < exposedSteps.x || step > exposedSteps.y) continue;
        // No masks in a packed series.
        AtlasSample atlasSample = AtlasSample(groupDensities[lane], true);
        if (knownTransparent)
            visitTransparentTimeStep(state, step, atlasSample, point.position, result);
        else
            visitTimeStep(state, step, atlasSample, point.position, result);
    }
}

// The groups whose bits `groups` sets, in time order; returns how many time-steps they hold. A loop
// over set bits runs as often as the pixel of the 8 with the most groups needs, where a loop over
// all groups fetched every group (llvmpipe runs a loop's body for all 8, masked).
int visitGroupsIn(uint groups, bool knownTransparent, inout CompositorState state, SamplePoint point,
                  float sharedValidity, inout TemporalSample result) {
    int lanes = 0;
    while (groups != 0u) {
        int group = findLSB(groups);
        groups &= groups - 1u;
        lanes += lanesOfGroup(group);
        visitGroup(state, point, group, knownTransparent, sharedValidity, result);
    }
    return lanes;
}

void accumulateTimeSteps(inout CompositorState state, SamplePoint point, inout TemporalSample result) {
    float sharedValidity = sharedValidityAt(point.aligned.voxel);
    result.fetches += PACKED_FETCHES_PER_SAMPLE;
#if PACKED_GROUP_MASKS
    uint visibleGroups = visibleGroupsAt(point.aligned);
    if (COMPOSITOR_IGNORES_TRANSPARENT) {
        // Only the groups with a time-step visible in the sample's brick: every time-step of the
        // others is transparent here, which such a compositor leaves out (they count as met).
        int visitedLanes = visitGroupsIn(visibleGroups, false, state, point, sharedValidity, result);
        result.contributing += timeStepCount - visitedLanes;
        return;
    }
    if (!COMPOSITOR_READS_TRANSPARENT_COLOUR) {
        // Every density counts (a change, a spread, a time of maximum), but the groups outside the
        // mask need no STF lookups: first those, then the visible ones in time order (the
        // compositors break ties by time-step, or only among visible time-steps).
        uint allGroups = packedGroupCount >= 32 ? ~0u : (1u << packedGroupCount) - 1u;
        visitGroupsIn(allGroups & ~visibleGroups, true, state, point, sharedValidity, result);
        visitGroupsIn(visibleGroups, false, state, point, sharedValidity, result);
        return;
    }
#endif
    for (int group = 0; group < packedGroupCount; ++group)
        visitGroup(state, point, group, false, sharedValidity, result);
}
