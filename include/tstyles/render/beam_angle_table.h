// The beam angles of beam (sonar) grids as the shaders read them (shaders/beam_grid.glsl): each
// axis' angles in radians, followed by a bucket lookup that finds the two beams around an angle with
// one read and at most one step, so the lookup needs no loop. GL-free.
//
// Why no loop: Mesa's llvmpipe ends every loop of a shader invocation once 65535 loop iterations have
// run in it in all (per 8 pixels); a binary search over the beams, run a few times per time-step and
// sample, used that up halfway along the sonar survey's rays (docs/performance.md, "Sonar").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tstyles {

// The most buckets one axis' lookup may take: enough for neighbouring beams 1/32768 of the fan's
// width apart.
inline constexpr int kMaxBeamBuckets = 65536;

// Appends one axis' angles (degrees in, radians stored) and its lookup to `table`: the angles, then
// 1 / bucket width (radians), the bucket count, and each bucket's lower beam (the last beam at or
// below the bucket's start, at most count - 2). Buckets are at most half the narrowest gap between
// neighbouring beams wide. Returns where the angles start. Angles so unevenly spread that this would
// take more than kMaxBeamBuckets buckets are refused with an InputError naming `file` and `field`.
int appendBeamAngleRun(const std::vector<double>& anglesDeg, std::vector<float>& table,
                       const std::filesystem::path& file, const std::string& field);

// The fractional beam index of `angleRad` among the `count` angles starting at `first` (0 at the
// first beam, 1 at the second, linear between), or -1 outside [first, last]: what
// fractionalBeamIndex in shaders/beam_grid.glsl computes, in the same float arithmetic.
float lookUpBeamIndex(const std::vector<float>& table, int first, int count, float angleRad);

}  // namespace tstyles
