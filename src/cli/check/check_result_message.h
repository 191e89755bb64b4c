// A `tstyles check` case result as bytes, for `check --distributed`: the process that rendered a
// case sends it to process 0, which reports every case. Images travel as their float values, so the
// report and `--update` see exactly what the rendering process saw.
#pragma once

#include <cstdint>
#include <vector>

#include "check_report.h"

namespace tstyles::cli {

// CBOR (through nlohmann-json) of every field; the images' float RGBA as byte strings in this
// machine's byte order (the processes of one MPI run share it).
std::vector<std::uint8_t> encodeCaseResult(const CaseResult& result);
// The result `encodeCaseResult` was given; std::runtime_error for bytes it did not write.
CaseResult decodeCaseResult(const std::vector<std::uint8_t>& bytes);

}  // namespace tstyles::cli
