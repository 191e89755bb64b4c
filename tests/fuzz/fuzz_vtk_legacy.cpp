// Fuzz target: a legacy VTK file (.vtk): the keywords of the three structured data sets, ASCII
// numbers and big-endian binary arrays, lookup tables, FIELD and METADATA blocks, then the values
// of every time-step.
#include "fuzz_series_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    tstyles_fuzz::openSeriesFile("input.vtk", tstyles_fuzz::asText(data, size));
    return 0;
}
