// The walk over the time-steps at a sample through the ray's list (overlap_extraction.glsl): only
// the time-steps whose entry/exit interval contains the sample, each at the voxel position stepped
// along the ray (voxel_rays.glsl), with empty-space skipping over all of them at once.
#include "variant_switches.glsl"
#include "ray.glsl"
#include "overlap_extraction.glsl"
#include "voxel_rays.glsl"
#include "volume_sampling.glsl"
#include "time_step_visit.glsl"

const bool WALK_SKIPS_EMPTY_SPACE = true;

struct SamplePoint {
    vec3 position;  // in the world
    float t;        // on the ray
};

void prepareWalk(Ray ray) {
    prepareVoxelRays(ray);
}

void advanceWalk(float t) {
    advanceLiveWindow(t);
}

// How many time-steps the walk has in reach at its last sample (the slots of the live window): what the
// parts of the pass that `bench --stages` times keep of the walk (RAYCAST_PART).
int timeStepsInReach() {
    return liveEnd - liveBegin;
}

SamplePoint samplePointAt(vec3 position, float t) {
    return SamplePoint(position, t);
}

bool listSlotContains(int slot, float t) {
    return t >= activeIntervals[slot].x && t <= activeIntervals[slot].y;
}

// Whether all time-steps at the sample lie in empty bricks: -1 if not, else where the first of
// their bricks ends. Without SKIP_EMPTY_BRICKS always -1, and the test is not in the program.
float emptySpaceUntil(SamplePoint point) {
#if !SKIP_EMPTY_BRICKS
    return -1.0;
#endif
    float emptyUntil = 1.0e30;
    bool anyStep = false;
    for (int i = liveBegin; i < liveEnd; ++i) {
        if (!listSlotContains(i, point.t)) continue;
        int step = activeSteps[i];
        anyStep = true;
        // Outside a beam fan or a structured grid but inside its proxy: nothing here, and no jump
        // past this sample.
        vec4 voxelInShape = voxelInShapeAtSample(i, step, point.position, point.t);
        if (voxelInShape.w < 0.5) {
            emptyUntil = min(emptyUntil, point.t);
            continue;
        }
        vec3 voxel = voxelInShape.xyz;
        int reach = emptyReachAt(step, voxel);
        if (reach < 0) return -1.0;
#if ALL_AFFINE
        vec3 gridLocal = voxel;
#else
        vec3 gridLocal = slotAffine(i) ? voxel : gridLocalAtSample(i, point.t);
#endif
        emptyUntil = min(emptyUntil,
                         emptyBrickEnd(step, voxel, gridLocal, point.t, point.position, slotVoxelDirection(i), reach));
    }
    return anyStep ? emptyUntil : -1.0;
}

void accumulateTimeSteps(inout CompositorState state, SamplePoint point, inout TemporalSample result) {
    for (int i = liveBegin; i < liveEnd; ++i) {
        if (!listSlotContains(i, point.t)) continue;
        int step = activeSteps[i];
        vec4 voxelInShape = voxelInShapeAtSample(i, step, point.position, point.t);
        // Inside the time-step's interval but outside its grid (a beam fan's proxy encloses the fan
        // only conservatively): nothing to composite, but the time-step still counts, so that the
        // ray does not jump past the rest of its interval.
        if (voxelInShape.w < 0.5) {
            result.contributing += 1;
            continue;
        }
        result.fetches += 1;
        visitTimeStep(state, step, sampleAtlas(atlasCoordinateOfVoxel(step, voxelInShape.xyz)), point.position, result);
    }
}
