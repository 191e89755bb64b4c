// Fuzz target: a VTK XML ImageData file (.vti): the XML, the binary headers, base64 and the
// zlib/LZ4/LZMA blocks, then the values of every time-step.
#include "fuzz_series_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    tstyles_fuzz::openSeriesFile("input.vti", tstyles_fuzz::asText(data, size));
    return 0;
}
