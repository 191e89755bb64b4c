// The ray in the voxel coordinates of each time-step it meets, set up once per pixel: where a
// time-step's world -> voxel map is affine (TimeStepInfo.flags.x), a sample's voxel position is
// origin + t * direction, with no matrix read or product per sample. Along uneven rectilinear axes
// that is the grid-local position, which the axis' node lookup turns into a node index; structured
// and beam grids take the general voxelCoordinate() at every sample.
#include "ray.glsl"
#include "overlap_extraction.glsl"
#include "volume_sampling.glsl"
#if PER_RAY_CACHES
vec3 activeVoxelOrigin[MAX_TIME_STEPS];     // voxel coordinates at t = 0 (affine time-steps)
vec3 activeVoxelDirection[MAX_TIME_STEPS];  // voxel units per unit of t (affine time-steps)
vec3 activeVoxelUpper[MAX_TIME_STEPS];      // dims - 1: where the clamp to the grid ends
bool activeAffine[MAX_TIME_STEPS];
#if BEAM_GRIDS
bool activeBeam[MAX_TIME_STEPS];
#if EVEN_BEAMS
EvenBeamFan activeBeamFan[MAX_TIME_STEPS];
#endif
#endif
#else
// Without the caches (a GPU: arrays indexed at run time live in slow per-thread memory there, where
// a time-step's record in the storage buffer is read by a whole warp at once), only the ray.
Ray voxelRay;
#endif

// After extractVolumeOverlap: fills the caches above for the ray's list of time-steps.
void prepareVoxelRays(Ray ray) {
#if PER_RAY_CACHES
    for (int i = 0; i < activeCount; ++i) {
        int step = activeSteps[i];
        mat4 worldToVoxel = timeSteps.steps[step].worldToVoxel;
        activeAffine[i] = timeSteps.steps[step].flags.x != 0;
        activeVoxelOrigin[i] = (worldToVoxel * vec4(ray.origin, 1.0)).xyz;
        activeVoxelDirection[i] = mat3(worldToVoxel) * ray.direction;
        activeVoxelUpper[i] = timeSteps.steps[step].dims.xyz - 1.0;
#if BEAM_GRIDS
        activeBeam[i] = isBeamGrid(step);
#if EVEN_BEAMS
        activeBeamFan[i] = evenBeamFanOf(step);
#endif
#endif
    }
#else
    voxelRay = ray;
#endif
}

// What the caches hold for the time-step in a slot of the ray's list, cached or worked out again.
vec3 slotVoxelDirection(int slot) {
#if PER_RAY_CACHES
    return activeVoxelDirection[slot];
#else
    return mat3(timeSteps.steps[activeSteps[slot]].worldToVoxel) * voxelRay.direction;
#endif
}

vec3 slotVoxelUpper(int slot) {
#if PER_RAY_CACHES
    return activeVoxelUpper[slot];
#else
    return timeSteps.steps[activeSteps[slot]].dims.xyz - 1.0;
#endif
}

bool slotAffine(int slot) {
#if PER_RAY_CACHES
    return activeAffine[slot];
#else
    return timeSteps.steps[activeSteps[slot]].flags.x != 0;
#endif
}

#if BEAM_GRIDS
bool slotBeam(int slot) {
#if PER_RAY_CACHES
    return ONLY_BEAM_GRIDS || activeBeam[slot];
#else
    return isBeamGrid(activeSteps[slot]);
#endif
}

#if EVEN_BEAMS
EvenBeamFan slotBeamFan(int slot) {
#if PER_RAY_CACHES
    return activeBeamFan[slot];
#else
    return evenBeamFanOf(activeSteps[slot]);
#endif
}
#endif
#endif

// voxelCoordinate(step, position) for the sample at ray parameter t, `slot` being the time-step's
// place in the ray's list.
// ALL_AFFINE (volume_sampling.glsl) leaves the general path out of the program.

// The sample in worldToVoxel's space along the ray of an affine or rectilinear time-step (before
// the node lookup of uneven axes); along even axes, the unclamped voxel position.
vec3 gridLocalAtSample(int slot, float t) {
#if PER_RAY_CACHES
    return activeVoxelOrigin[slot] + t * activeVoxelDirection[slot];
#else
    return (timeSteps.steps[activeSteps[slot]].worldToVoxel * vec4(voxelRay.origin + t * voxelRay.direction, 1.0)).xyz;
#endif
}

vec3 voxelAtSample(int slot, int step, vec3 position, float t) {
    vec3 voxel = gridLocalAtSample(slot, t);
#if !ALL_AFFINE
    if (!slotAffine(slot)) {
        if (isStructured(step) || isBeamGrid(step)) return voxelCoordinate(step, position);
        voxel = applyUnevenAxes(step, voxel);
    }
#endif
    return clamp(voxel, vec3(0.0), slotVoxelUpper(slot));
}

// The sample's clamped voxel position in the slot's time-step and, in w, whether the sample lies in
// the grid's shape (insideGridShape): for a beam grid one mapping of the ray's grid-local position
// gives both, where insideGridShape and voxelAtSample would each map the world position again.
vec4 voxelInShapeAtSample(int slot, int step, vec3 position, float t) {
#if BEAM_GRIDS
    if (slotBeam(slot)) {
#if EVEN_BEAMS
        vec4 beam = evenBeamVoxel(slotBeamFan(slot), slotVoxelUpper(slot), gridLocalAtSample(slot, t));
#else
        vec4 beam = beamVoxel(step, gridLocalAtSample(slot, t));
#endif
        return vec4(clamp(beam.xyz, vec3(0.0), slotVoxelUpper(slot)), beam.w);
    }
#endif
    return vec4(voxelAtSample(slot, step, position, t), insideGridShape(step, position) ? 1.0 : 0.0);
}
