// The benchmark's baseline walk: every time-step is tested at every sample (is the sample inside
// its grid?) instead of walking the ray's list of time-steps, and nothing is skipped.
#include "variant_switches.glsl"
#include "ray.glsl"
#include "overlap_extraction.glsl"
#include "volume_sampling.glsl"
#include "time_step_visit.glsl"

const bool WALK_SKIPS_EMPTY_SPACE = false;

struct SamplePoint {
    vec3 position;  // in the world
    float t;        // on the ray
};

void prepareWalk(Ray ray) {}

void advanceWalk(float t) {}

// How many time-steps the walk has in reach at its last sample (every time-step): what the
// parts of the pass that `bench --stages` times keep of the walk (RAYCAST_PART).
int timeStepsInReach() {
    return timeStepCount;
}

SamplePoint samplePointAt(vec3 position, float t) {
    return SamplePoint(position, t);
}

float emptySpaceUntil(SamplePoint point) {
    return -1.0;
}

void accumulateTimeSteps(inout CompositorState state, SamplePoint point, inout TemporalSample result) {
    for (int step = 0; step < timeStepCount; ++step) {
        if (step < exposedSteps.x || step > exposedSteps.y) continue;
        if (!insideGrid(step, point.position)) continue;
        if (!insideGridShape(step, point.position)) continue;
        vec3 atlasPosition = atlasCoordinateOfVoxel(step, voxelCoordinate(step, point.position));
        result.fetches += 1;
        visitTimeStep(state, step, sampleAtlas(atlasPosition), point.position, result);
    }
}
