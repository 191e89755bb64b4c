// How much memory this process has held: what the distributed commands report per process.
#pragma once

#include <cstdint>

namespace tstyles {

// The most resident memory this process has had so far (getrusage's maximum resident set), in
// bytes: its own data and the OpenGL driver's (llvmpipe keeps textures in host memory).
std::uint64_t peakResidentBytes();

}  // namespace tstyles
