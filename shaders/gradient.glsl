// Density gradients for lit-sphere shading: central differences one voxel apart in the time-step's
// own grid (one-sided at its faces), turned into world space through the grid's placement and
// spacing, so anisotropic and rotated grids shade correctly.
vec3 beamWorldGradient(int step, vec3 worldPosition);

vec3 worldGradient(int step, vec3 worldPosition) {
    if (isBeamGrid(step)) return beamWorldGradient(step, worldPosition);
    vec3 voxel = voxelCoordinate(step, worldPosition);
    vec3 upperLimit = timeSteps.steps[step].dims.xyz - 1.0;
    vec3 gradient;
    for (int axis = 0; axis < 3; ++axis) {
        vec3 offset = vec3(0.0);
        offset[axis] = 1.0;
        vec3 upper = min(voxel + offset, upperLimit);
        vec3 lower = max(voxel - offset, vec3(0.0));
        float span = upper[axis] - lower[axis];
        float difference = sampleDensity(atlasCoordinateOfVoxel(step, upper)) -
                           sampleDensity(atlasCoordinateOfVoxel(step, lower));
        gradient[axis] = span > 0.0 ? difference / span : 0.0;
    }
    // voxel = M * world, so d(density)/d(world) = transpose(M) * d(density)/d(voxel).
    return transpose(mat3(timeSteps.steps[step].worldToVoxel)) * gradient;
}

// A beam grid's voxel coordinates are not affine in world position, so its gradient is taken by
// central differences along the world axes, one range spacing to either side.
vec3 beamWorldGradient(int step, vec3 worldPosition) {
    float h = timeSteps.steps[step].beamRange.z;
    vec3 gradient;
    for (int axis = 0; axis < 3; ++axis) {
        vec3 offset = vec3(0.0);
        offset[axis] = h;
        gradient[axis] = (sampleDensity(atlasCoordinate(step, worldPosition + offset)) -
                          sampleDensity(atlasCoordinate(step, worldPosition - offset))) /
                         (2.0 * h);
    }
    return gradient;
}
