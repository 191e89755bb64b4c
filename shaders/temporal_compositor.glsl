// Temporal compositors (paper 5.3): at a sample, every time-step whose interval contains it
// contributes its density, its mask and its STF classification; the compositor turns those n
// values into a temporal characteristic, reads the TSTF and applies the final processing. Styles
// need a normal, so gradients are computed only for the time-steps that end up visible.
#define TC_MAX_INTENSITY_PROJECTION 0
#define TC_AVERAGE 1
#define TC_MAX_DENSITY_CHANGE 2

#ifndef TEMPORAL_COMPOSITOR
#define TEMPORAL_COMPOSITOR TC_MAX_INTENSITY_PROJECTION
#endif
// 1 when any transfer function of the scene uses a lit-sphere style.
#ifndef STYLED
#define STYLED 1
#endif
// 1 for the benchmark's baseline: every time-step is tested at every sample (is the sample inside
// its grid?) instead of walking the ray's list of time-steps, and nothing is skipped.
#ifndef NAIVE_RAYCASTER
#define NAIVE_RAYCASTER 0
#endif

// The max density change is scaled from [changeRange.x, changeRange.y] to [0, 1].
uniform vec2 changeRange;

struct TemporalSample {
    vec4 colorOpacity;  // colour and opacity per reference length
    int contributing;   // how many time-steps contain the sample
    int fetches;        // volume texture fetches spent
    // > 0 when every time-step at the sample is in an empty brick: the ray may skip to here.
    float emptyUntil;
};

// The loop over the time-steps that contain the sample at ray parameter t; `step` is the time-step.
// DENSITY_AT_SAMPLE declares the time-step's `density` (and `atlasPosition`) and counts fetches.
#if NAIVE_RAYCASTER
#define FOR_EACH_TIME_STEP_AT_SAMPLE                                                             \
    for (int step = 0; step < timeStepCount; ++step) {                                           \
        if (step < exposedSteps.x || step > exposedSteps.y) continue;                           \
        if (!insideGrid(step, position)) continue;
#define END_FOR_EACH_TIME_STEP }
#elif PACKED_ALIGNED
// Every time-step contains every sample of the ray (they share one interval): groups of four,
// one fetch per group (packed_time_steps.glsl), counted in the compositor's `result`.
#define FOR_EACH_TIME_STEP_AT_SAMPLE                                                             \
    vec3 alignedVoxel = aligned.voxel;                                                           \
    float sharedValidity = sharedValidityAt(alignedVoxel);                                       \
    result.fetches += PACKED_FETCHES_PER_SAMPLE;                                                 \
    for (int group = 0; group < packedGroupCount; ++group) {                                     \
        vec4 groupDensities = packedDensities(group, alignedVoxel, sharedValidity);              \
        result.fetches += PACKED_FETCHES_PER_GROUP;                                              \
        for (int lane = 0; lane < 4; ++lane) {                                                   \
            int step = 4 * group + lane;                                                         \
            if (step >= timeStepCount) break;                                                    \
            if (step < exposedSteps.x || step > exposedSteps.y) continue;
#define END_FOR_EACH_TIME_STEP }}
#define DENSITY_AT_SAMPLE                                                                        \
    vec3 atlasPosition = vec3(0.0); /* no masks in a packed series */                            \
    float density = groupDensities[lane];
#else
#define FOR_EACH_TIME_STEP_AT_SAMPLE                                                             \
    for (int i = liveBegin; i < liveEnd; ++i) {                                                  \
        if (t < activeIntervals[i].x || t > activeIntervals[i].y) continue;                      \
        int step = activeSteps[i];
#define END_FOR_EACH_TIME_STEP }
#endif

// The time-step's voxel position at the sample, inside FOR_EACH_TIME_STEP_AT_SAMPLE.
#if NAIVE_RAYCASTER
#define VOXEL_AT_SAMPLE voxelCoordinate(step, position)
#else
#define VOXEL_AT_SAMPLE voxelAtSample(i, step, position, t)
#endif
#if !PACKED_ALIGNED
#define DENSITY_AT_SAMPLE                                                                        \
    vec3 atlasPosition = atlasCoordinateOfVoxel(step, VOXEL_AT_SAMPLE);                          \
    float density = sampleDensity(atlasPosition);                                                \
    result.fetches += 1;
#endif

#if !NAIVE_RAYCASTER && !PACKED_ALIGNED
// Whether all time-steps at the sample lie in empty bricks; if so, where the first brick ends.
float emptySpaceUntil(vec3 position, float t) {
    float emptyUntil = 1.0e30;
    bool anyStep = false;
    FOR_EACH_TIME_STEP_AT_SAMPLE
        anyStep = true;
        // Outside a beam fan or a structured grid but inside its proxy: nothing here, and no jump
        // past this sample.
        if (!insideGridShape(step, position)) {
            emptyUntil = min(emptyUntil, t);
            continue;
        }
        vec3 voxel = VOXEL_AT_SAMPLE;
        if (brickVisible(step, voxel)) return -1.0;
#if ALL_AFFINE
        vec3 gridLocal = voxel;
#else
        vec3 gridLocal = activeAffine[i] ? voxel : gridLocalAtSample(i, t);
#endif
        emptyUntil = min(emptyUntil, emptyBrickEnd(step, voxel, gridLocal, t, position, activeVoxelDirection[i]));
    END_FOR_EACH_TIME_STEP
    return anyStep ? emptyUntil : -1.0;
}
#endif

// Where the time-step's style is read at this sample (6 fetches when styled).
SphereCoordinate styleCoordinate(int step, vec3 position, inout int fetches) {
#if STYLED
    fetches += 6;
    return sphereCoordinate(worldGradient(step, position));
#else
    return SphereCoordinate(vec2(0.5));
#endif
}

TemporalSample compositeTemporal(vec3 position, float t) {
    TemporalSample result = TemporalSample(vec4(0.0), 0, 0, -1.0);
#if !NAIVE_RAYCASTER
    // Skip transparent regions of all time-steps at once. The max density change needs every
    // density once any time-step is visible, so the test comes before the real work.
#if PACKED_ALIGNED
    AlignedSample aligned = alignedSampleAt(t);
    result.emptyUntil = packedEmptySpaceUntil(aligned, t);
#else
    result.emptyUntil = emptySpaceUntil(position, t);
#endif
    if (result.emptyUntil > 0.0) {
        result.contributing = 1;
        return result;
    }
#endif
#if TEMPORAL_COMPOSITOR == TC_MAX_INTENSITY_PROJECTION
    // The time-step with the highest STF opacity wins. Inside overlapping opaque bodies the STF
    // opacities tie; then the time-step that the index TSTF shows most strongly wins (the focus of
    // Figure 1 stays opaque where its neighbours overlap it), then the earlier time-step.
    int winner = -1;
    float winnerDensity = 0.0;
    vec4 winnerStf = vec4(0.0);
    vec4 winnerTstf = vec4(0.0);
    bool winnerInMask = false;
#elif TEMPORAL_COMPOSITOR == TC_AVERAGE
    vec4 premultipliedSum = vec4(0.0);
    int nonTransparent = 0;
#else
    float minimumDensity = 1.0;
    float maximumDensity = 0.0;
    float strongestDensity = 0.0;
    vec4 strongestStf = vec4(0.0);
    int strongestStep = -1;
    bool anyInMask = false;
    int withData = 0;  // time-steps with data at the sample: a change needs two
#endif

    FOR_EACH_TIME_STEP_AT_SAMPLE
#if !PACKED_ALIGNED
        // (Packed series are rectilinear: every sample in the interval is in the grid.)
        if (!insideGridShape(step, position)) continue;
#endif
        DENSITY_AT_SAMPLE
        result.contributing += 1;
        // No data here: transparent, and left out of the temporal characteristic.
        if (isMissingDensity(density)) continue;
        bool inMask = insideMask(step, atlasPosition);
        vec4 stf = classifyStf(density);
#if HAS_MASKS
        result.fetches += timeSteps.steps[step].dims.w > 0.5 ? 1 : 0;
#endif
#if TEMPORAL_COMPOSITOR == TC_MAX_INTENSITY_PROJECTION
        if (stf.a >= winnerStf.a && stf.a > 0.0) {
            vec4 tstf = classifyIndexTstf(step);
            bool stronger = stf.a > winnerStf.a || tstf.a > winnerTstf.a ||
                            (tstf.a == winnerTstf.a && step < winner);
            if (stronger) {
                winner = step;
                winnerDensity = density;
                winnerStf = stf;
                winnerTstf = tstf;
                winnerInMask = inMask;
            }
        }
#elif TEMPORAL_COMPOSITOR == TC_AVERAGE
        if (stf.a <= 0.0) continue;
        vec4 tstf = classifyIndexTstf(step);
        SphereCoordinate sphere = styleCoordinate(step, position, result.fetches);
        vec4 styled = finalProcessing(applyStyle(STF_TRACK, density, stf, sphere),
                                      applyStyle(INDEX_TSTF_TRACK, float(step), tstf, sphere), inMask);
        if (styled.a <= 0.0) continue;
        premultipliedSum += vec4(styled.rgb * styled.a, styled.a);
        nonTransparent += 1;
#else
        minimumDensity = min(minimumDensity, density);
        maximumDensity = max(maximumDensity, density);
        anyInMask = anyInMask || inMask;
        withData += 1;
        if (stf.a > strongestStf.a || strongestStep < 0) {
            strongestStf = stf;
            strongestStep = step;
            strongestDensity = density;
        }
#endif
    END_FOR_EACH_TIME_STEP

#if TEMPORAL_COMPOSITOR == TC_MAX_INTENSITY_PROJECTION
    if (winner >= 0) {
        SphereCoordinate sphere = styleCoordinate(winner, position, result.fetches);
        result.colorOpacity = finalProcessing(applyStyle(STF_TRACK, winnerDensity, winnerStf, sphere),
                                              applyStyle(INDEX_TSTF_TRACK, float(winner), winnerTstf, sphere),
                                              winnerInMask);
    }
#elif TEMPORAL_COMPOSITOR == TC_AVERAGE
    // Opacities are averaged; colours are averaged weighted by opacity, so a faint time-step does
    // not wash out the colour of an opaque one.
    if (nonTransparent > 0)
        result.colorOpacity = vec4(premultipliedSum.rgb / premultipliedSum.a,
                                   premultipliedSum.a / float(nonTransparent));
#else
    if (strongestStf.a > 0.0 && withData >= 1) {
        SphereCoordinate sphere = styleCoordinate(strongestStep, position, result.fetches);
        vec4 stf = applyStyle(STF_TRACK, strongestDensity, strongestStf, sphere);
        if (withData >= 2) {
            float change = (maximumDensity - minimumDensity - changeRange.x) / (changeRange.y - changeRange.x);
            vec4 tstf = applyStyle(GRADIENT_TSTF_TRACK, clamp(change, 0.0, 1.0), classifyGradientTstf(change), sphere);
            result.colorOpacity = finalProcessing(stf, tstf, anyInMask);
        } else {
            // Change is undefined where only one time-step is present: the time-invariant STF shows.
            result.colorOpacity = stf;
        }
    }
#endif
    return result;
}
