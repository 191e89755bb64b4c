// Beam (sonar) grids: a sample's place in a fan of beams. The transducer sits at the grid-local
// origin looking along +z; azimuth is the angle in the x-z plane, elevation the angle in the y-z
// plane, so the fan's sides are planes through the transducer. A time-step's worldToVoxel takes
// world positions to grid-local ones; from there (azimuth, elevation, range) give the fractional
// sample (beam across, beam along, range sample). Mirrors tstyles/data/beam_geometry.h.
#include "contract.glsl"
#include "variant_switches.glsl"
#include "time_steps.glsl"

// Every beam grid's beam angles in radians, one run per axis and time-step (TimeStepInfo.grid.yz
// says where each run starts): uneven beam spacing needs the list, not just the extent. Each run is
// followed by its bucket lookup (render/beam_angle_table.h).
layout(std430, binding = BEAM_ANGLE_BUFFER) readonly buffer BeamAngles {
    float angles[];
} beamAngles;

bool isBeamGrid(int step) {
#if BEAM_GRIDS
    return ONLY_BEAM_GRIDS || timeSteps.steps[step].grid.x == GRID_BEAM;
#else
    return false;
#endif
}

// atan(lateral, depth) where depth > 0 (inside a fan; elsewhere any angle does, the sample is
// outside). The built-in arc tangent is a long instruction sequence on a GPU; this odd minimax
// polynomial of degree 11 on [-1, 1] (with atan(a) = sign(a) pi/2 - atan(1/a) beyond) is within
// 1.7e-6 radians of it, a thousandth of a beam for fans of 500 beams per radian, and made the
// sonar 12-14 % faster on an NVIDIA H200 (docs/performance.md, "Where the sonar's GPU time goes").
float fanAngle(float lateral, float depth) {
    float ratio = lateral / depth;
    bool beyondOne = abs(ratio) > 1.0;
    float u = beyondOne ? 1.0 / ratio : ratio;
    float u2 = u * u;
    float angle = u * (0.99997726 + u2 * (-0.33262347 + u2 * (0.19354346 + u2 * (-0.11643287 +
                  u2 * (0.05265332 + u2 * -0.01172120)))));
    return beyondOne ? sign(ratio) * 1.57079633 - angle : angle;
}

// The fractional index of `angle` among `count` increasing angles from `first` on; -1 outside.
// Mirrors lookUpBeamIndex (tstyles/render/beam_angle_table.h). After the angles: 1 / bucket width,
// the bucket count, each bucket's lower beam; buckets are at most half the narrowest gap between
// beams wide, so the beam pair is the bucket's or one step away. No loop here on purpose: llvmpipe
// ends all loops of an invocation after 65535 iterations in all, and this runs several times per
// time-step and sample (docs/performance.md, "Sonar").
float fractionalBeamIndex(int first, int count, float angle) {
    float firstAngle = beamAngles.angles[first];
    if (angle < firstAngle || angle > beamAngles.angles[first + count - 1]) return -1.0;
    int lookup = first + count;
    int buckets = int(beamAngles.angles[lookup + 1]);
    int bucket = clamp(int((angle - firstAngle) * beamAngles.angles[lookup]), 0, buckets - 1);
    int low = int(beamAngles.angles[lookup + 2 + bucket]);
    if (low < count - 2 && beamAngles.angles[first + low + 1] <= angle)
        low += 1;
    else if (low > 0 && beamAngles.angles[first + low] > angle)
        low -= 1;
    float lowAngle = beamAngles.angles[first + low];
    float highAngle = beamAngles.angles[first + low + 1];
    return float(low) + clamp((angle - lowAngle) / (highAngle - lowAngle), 0.0, 1.0);
}

// A fan whose beams are evenly spaced on both axes (EVEN_BEAMS): a beam index is then linear in its
// angle, so a sample's place needs no angle list, only these numbers from the time-step's record
// (TimeStepInfo.evenBeamFan), which a ray reads once per time-step (voxel_rays.glsl) with per-ray
// caches, and a GPU at every sample.
struct EvenBeamFan {
    vec4 angles;      // x, z: the first azimuth and elevation (radians); y, w: beams per radian
    vec4 ranges;      // x, y: minimum and maximum range; z: range samples per unit of range
};

EvenBeamFan evenBeamFanOf(int step) {
    TimeStepInfo info = timeSteps.steps[step];
    return EvenBeamFan(info.evenBeamFan, vec4(info.beamRange.xy, info.beamRange.w, 0.0));
}

// beamVoxel() for an evenly spaced fan with samples 0 .. lastSample (dims - 1); outside the fan xyz
// run on past its faces (beamVoxel's callers clamp them to the grid).
vec4 evenBeamVoxel(EvenBeamFan fan, vec3 lastSample, vec3 local) {
    float range = length(local);
    float across = (fanAngle(local.x, local.z) - fan.angles.x) * fan.angles.y;
    float along = (fanAngle(local.y, local.z) - fan.angles.z) * fan.angles.w;
    float rangeSample = (range - fan.ranges.x) * fan.ranges.z;
    bool inside = local.z > 0.0 && across >= 0.0 && across <= lastSample.x && along >= 0.0 &&
                  along <= lastSample.y && range >= fan.ranges.x && range <= fan.ranges.y;
    return vec4(across, along, rangeSample, inside ? 1.0 : 0.0);
}

// The derivatives of evenBeamVoxel's sample coordinates by the grid-local position: row 0 is the
// gradient of the beam index across, row 1 along, row 2 of the range sample.
mat3 evenBeamJacobian(EvenBeamFan fan, vec3 local) {
    vec3 acrossGradient = fan.angles.y * vec3(local.z, 0.0, -local.x) / dot(local.xz, local.xz);
    vec3 alongGradient = fan.angles.w * vec3(0.0, local.z, -local.y) / dot(local.yz, local.yz);
    vec3 rangeGradient = fan.ranges.z * local / length(local);
    return transpose(mat3(acrossGradient, alongGradient, rangeGradient));
}

// xyz: fractional sample coordinates of a grid-local position; w: 1 inside the fan, 0 outside.
vec4 beamVoxel(int step, vec3 local) {
#if EVEN_BEAMS
    return evenBeamVoxel(evenBeamFanOf(step), timeSteps.steps[step].dims.xyz - 1.0, local);
#endif
    TimeStepInfo info = timeSteps.steps[step];
    float range = length(local);
    float across = fractionalBeamIndex(info.grid.y, int(info.dims.x), fanAngle(local.x, local.z));
    float along = fractionalBeamIndex(info.grid.z, int(info.dims.y), fanAngle(local.y, local.z));
    float rangeSample = (range - info.beamRange.x) / (info.beamRange.y - info.beamRange.x) * (info.dims.z - 1.0);
    bool inside = local.z > 0.0 && across >= 0.0 && along >= 0.0 && range >= info.beamRange.x &&
                  range <= info.beamRange.y;
    return vec4(across, along, rangeSample, inside ? 1.0 : 0.0);
}

// Empty-space skipping in a beam grid: a brick is bounded by four planes through the transducer
// and two spheres, so the distance from the sample to the nearest of them is a step the ray can
// take without leaving the brick, whatever its direction (world and grid-local distances agree).
float beamBrickExit(int step, vec3 brickLower, vec3 brickUpper, vec3 local, float t) {
    TimeStepInfo info = timeSteps.steps[step];
    float azimuthLow = beamAngles.angles[info.grid.y + int(brickLower.x)];
    float azimuthHigh = beamAngles.angles[info.grid.y + int(brickUpper.x)];
    float elevationLow = beamAngles.angles[info.grid.z + int(brickLower.y)];
    float elevationHigh = beamAngles.angles[info.grid.z + int(brickUpper.y)];
    float rangeSpacing = (info.beamRange.y - info.beamRange.x) / (info.dims.z - 1.0);
    float range = length(local);
    float distance = min(range - (info.beamRange.x + brickLower.z * rangeSpacing),
                         info.beamRange.x + brickUpper.z * rangeSpacing - range);
    distance = min(distance, abs(local.x * cos(azimuthLow) - local.z * sin(azimuthLow)));
    distance = min(distance, abs(local.x * cos(azimuthHigh) - local.z * sin(azimuthHigh)));
    distance = min(distance, abs(local.y * cos(elevationLow) - local.z * sin(elevationLow)));
    distance = min(distance, abs(local.y * cos(elevationHigh) - local.z * sin(elevationHigh)));
    return t + max(distance, 0.0);
}
