// Density gradients on structured grids, for lit-sphere shading: central differences in world
// space (the map from world to computational coordinates is not affine, so the voxel-space
// differences of gradient.glsl would point the wrong way on curved grids). Where a neighbour
// lies outside the grid the difference is one-sided, as gradient.glsl does at a grid's faces.
float structuredDensityAt(int step, vec3 worldPosition, out bool inside) {
    vec4 mapped = inverseMapAt(step, worldPosition);
    inside = mapped.a >= 0.5;
    vec3 voxel = clamp(mapped.rgb, vec3(0.0), timeSteps.steps[step].dims.xyz - 1.0);
    return sampleDensity(atlasCoordinateOfVoxel(step, voxel));
}

vec3 structuredWorldGradient(int step, vec3 worldPosition) {
    float h = structuredGrids.steps[step].mapScale.w;
    bool centreInside;
    float centre = structuredDensityAt(step, worldPosition, centreInside);
    vec3 gradient;
    for (int axis = 0; axis < 3; ++axis) {
        vec3 offset = vec3(0.0);
        offset[axis] = h;
        bool upperInside, lowerInside;
        float upper = structuredDensityAt(step, worldPosition + offset, upperInside);
        float lower = structuredDensityAt(step, worldPosition - offset, lowerInside);
        float span = 2.0 * h;
        if (!upperInside) {
            upper = centre;
            span -= h;
        }
        if (!lowerInside) {
            lower = centre;
            span -= h;
        }
        gradient[axis] = span > 0.0 ? (upper - lower) / span : 0.0;
    }
    return gradient;
}
