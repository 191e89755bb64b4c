// Fuzz target: a Plot3D grid file and one solution (q) or function (f) file, opened as
// `tstyles render grid.xyz --solution flow.q` does. The input's first two bytes (little-endian)
// say how many of the bytes after the third are the grid file; the rest is the solution file, a
// function file (read as its first variable) when the third byte is odd.
#include <algorithm>
#include <string>

#include "fuzz_series_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 3) return -1;
    const std::size_t gridSize = std::min<std::size_t>(data[0] | (std::size_t(data[1]) << 8), size - 3);
    const bool function = (data[2] & 1) != 0;
    const std::string_view rest = tstyles_fuzz::asText(data + 3, size - 3);
    tstyles::ReadOptions options;
    options.solutionFiles = {tstyles_fuzz::writeScratchFile(function ? "flow.f" : "flow.q", rest.substr(gridSize))};
    if (function) options.variable = "function-0";
    tstyles_fuzz::openSeriesFile("grid.xyz", rest.substr(0, gridSize), options);
    return 0;
}
