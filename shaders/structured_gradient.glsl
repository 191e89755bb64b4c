// Density gradients on structured grids, for lit-sphere shading: central differences in world
// space (the map from world to computational coordinates is not affine, so the voxel-space
// differences of gradient.glsl would point the wrong way on curved grids).
vec3 structuredWorldGradient(int step, vec3 worldPosition) {
    float h = structuredGrids.steps[step].mapScale.w;
    vec3 gradient;
    for (int axis = 0; axis < 3; ++axis) {
        vec3 offset = vec3(0.0);
        offset[axis] = h;
        float upper = sampleDensity(atlasCoordinateOfVoxel(step, structuredVoxelCoordinate(step, worldPosition + offset)));
        float lower = sampleDensity(atlasCoordinateOfVoxel(step, structuredVoxelCoordinate(step, worldPosition - offset)));
        gradient[axis] = (upper - lower) / (2.0 * h);
    }
    return gradient;
}
