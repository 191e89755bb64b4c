// The temporal compositor at one sample (paper 5.3): every time-step whose interval contains the
// sample contributes its density, its mask and its STF classification; the program's compositor
// module (compositor.glsl: one of the tc_*.glsl files) turns those n values into a temporal
// characteristic, which the ray mode (ray_sample.glsl) styles through the transfer function it
// names (characteristic_style.glsl) where and when it needs the sample's temporal style. The
// program's walk (time_step_walk.glsl: walk_ray_list, walk_packed_groups or walk_naive) decides
// which time-steps are at the sample and how their densities are read.
#include "temporal_sample.glsl"
#include "compositor.glsl"
#include "time_step_walk.glsl"

// `changeFloor` (SKIP_UNCHANGING_BRICKS): the change over time a place must exceed to change the
// pixel (rayChangeFloor), or -1 where every place may.
TemporalSample compositeTemporal(vec3 position, float t, float changeFloor) {
    TemporalSample result = TemporalSample(transparentCharacteristic(), 0, 0, -1.0, -1.0);
    SamplePoint point = samplePointAt(position, t);
    // Skip transparent regions of all time-steps at once. The max density change needs every
    // density once any time-step is visible, so the test comes before the real work.
    if (WALK_SKIPS_EMPTY_SPACE) {
        result.emptyUntil = emptySpaceUntil(point);
        if (result.emptyUntil > 0.0) {
            result.contributing = 1;
            return result;
        }
    }
#if SKIP_UNCHANGING_BRICKS
    // And the bricks where nothing changes more than the ray's kept change: no sample of theirs
    // could replace it.
    if (changeFloor >= 0.0) {
        result.unchangingUntil = unchangingSpaceUntil(point, changeFloor);
        if (result.unchangingUntil > 0.0) {
            result.contributing = 1;
            return result;
        }
    }
#endif
    if (RAYCAST_PART == RAYCAST_PART_MARCH) {
        // The march alone (`bench --stages`): the sample is transparent, so the ray runs to its
        // exit, and jumps where the whole pass would, between time-steps (none in the walk's
        // reach); raycast.frag keeps what the walk found.
        result.contributing = timeStepsInReach();
        result.fetches = result.contributing;
        return result;
    }
    CompositorState state = compositorInit();
    accumulateTimeSteps(state, point, result);
    result.characteristic = compositorFinish(state, position, result.fetches);
    return result;
}
