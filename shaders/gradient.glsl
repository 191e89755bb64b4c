// Density gradients for lit-sphere shading: central differences one voxel apart in the time-step's
// own grid (one-sided at its faces), turned into world space through the grid's placement and
// spacing, so anisotropic, uneven and rotated grids shade correctly; structured and beam grids
// have their own (structured_gradient.glsl, beamWorldGradient below).
#include "volume_sampling.glsl"
#include "structured_gradient.glsl"

vec3 beamWorldGradient(int step, vec3 worldPosition);

#if PRECOMPUTED_GRADIENTS
// The node differences computed once per series (gradient_atlas.comp), in the density atlas'
// layout: one fetch, trilinearly filtered, instead of six. Rectilinear grids only
// (variant_switches.glsl). Alpha is 1 at nodes with data and 0 at nodes without.
layout(binding = GRADIENT_ATLAS_UNIT) uniform sampler3D gradientAtlas;
#endif

vec3 worldGradient(int step, vec3 worldPosition) {
#if PRECOMPUTED_GRADIENTS
    vec4 filtered = texture(gradientAtlas, atlasCoordinate(step, worldPosition));
    // Beside missing data: the mean over the nodes that have data (none: no slope).
    vec3 voxelGradient = MISSING_VALUES == 0 ? filtered.xyz : (filtered.a > 0.0 ? filtered.xyz / filtered.a : vec3(0.0));
    return transpose(mat3(timeSteps.steps[step].worldToVoxel)) * voxelGradient;
#endif
#if !ALL_AFFINE
    if (isStructured(step)) return structuredWorldGradient(step, worldPosition);
    if (isBeamGrid(step)) return beamWorldGradient(step, worldPosition);
#endif
    vec3 voxel = voxelCoordinate(step, worldPosition);
    vec3 upperLimit = timeSteps.steps[step].dims.xyz - 1.0;
    float centre = MISSING_DENSITY;  // read only when a neighbour has no data
    vec3 gradient;
    for (int axis = 0; axis < 3; ++axis) {
        vec3 offset = vec3(0.0);
        offset[axis] = 1.0;
        vec3 upper = min(voxel + offset, upperLimit);
        vec3 lower = max(voxel - offset, vec3(0.0));
        float upperDensity = sampleDensity(atlasCoordinateOfVoxel(step, upper));
        float lowerDensity = sampleDensity(atlasCoordinateOfVoxel(step, lower));
        // Beside missing data the difference is one-sided, towards the side that has data.
        if (isMissingDensity(upperDensity) || isMissingDensity(lowerDensity)) {
            if (isMissingDensity(centre)) centre = sampleDensity(atlasCoordinateOfVoxel(step, voxel));
            if (isMissingDensity(upperDensity)) {
                upperDensity = centre;
                upper = voxel;
            }
            if (isMissingDensity(lowerDensity)) {
                lowerDensity = centre;
                lower = voxel;
            }
        }
        // The span in worldToVoxel's coordinates: voxels, or grid-local units along an uneven axis.
#if ALL_AFFINE
        float span = upper[axis] - lower[axis];
#else
        float span = isUnevenAxis(step, axis)
                         ? nodePositionOf(step, axis, upper[axis]) - nodePositionOf(step, axis, lower[axis])
                         : upper[axis] - lower[axis];
#endif
        float difference = upperDensity - lowerDensity;
        bool bothHaveData = !isMissingDensity(upperDensity) && !isMissingDensity(lowerDensity);
        gradient[axis] = span > 0.0 && bothHaveData ? difference / span : 0.0;
    }
    // worldToVoxel's coordinates = M * world, so d(density)/d(world) = transpose(M) * their gradient.
    return transpose(mat3(timeSteps.steps[step].worldToVoxel)) * gradient;
}

// A beam grid's voxel coordinates are not affine in world position, so its gradient is taken by
// central differences along the world axes, one range spacing (h) to either side. worldToVoxel is
// rigid for a beam grid, so each offset is the grid-local position plus h times a column of it.
vec3 beamWorldGradient(int step, vec3 worldPosition) {
    float h = timeSteps.steps[step].beamRange.z;
    mat4 worldToLocal = timeSteps.steps[step].worldToVoxel;
    vec3 local = (worldToLocal * vec4(worldPosition, 1.0)).xyz;
    vec3 upperLimit = timeSteps.steps[step].dims.xyz - 1.0;
#if EVEN_BEAMS
    // The neighbours' sample coordinates to first order: the sample's own plus h times the fan's
    // Jacobian times the world axis. h is a range spacing, far below the radius of curvature of the
    // fan's coordinates (a range), so this is the six-mapping result to well under 1/255; it saves
    // six mappings (two arc tangents each) per styled time-step and sample.
    EvenBeamFan fan = evenBeamFanOf(step);
    vec3 voxel = evenBeamVoxel(fan, upperLimit, local).xyz;
    mat3 worldStepInSamples = h * evenBeamJacobian(fan, local) * mat3(worldToLocal);
#endif
    vec3 gradient;
    for (int axis = 0; axis < 3; ++axis) {
#if EVEN_BEAMS
        vec3 upper = clamp(voxel + worldStepInSamples[axis], vec3(0.0), upperLimit);
        vec3 lower = clamp(voxel - worldStepInSamples[axis], vec3(0.0), upperLimit);
#else
        vec3 offset = h * worldToLocal[axis].xyz;
        vec3 upper = clamp(beamVoxel(step, local + offset).xyz, vec3(0.0), upperLimit);
        vec3 lower = clamp(beamVoxel(step, local - offset).xyz, vec3(0.0), upperLimit);
#endif
        gradient[axis] = (sampleDensity(atlasCoordinateOfVoxel(step, upper)) -
                          sampleDensity(atlasCoordinateOfVoxel(step, lower))) /
                         (2.0 * h);
    }
    return gradient;
}
