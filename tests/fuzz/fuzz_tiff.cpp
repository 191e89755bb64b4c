// Fuzz target: one TIFF file (ImageJ hyperstack, OME-TIFF or plain pages) through libtiff after our
// checks, the ImageJ description and OME-XML parsers, then every plane of every time-step.
#include "fuzz_series_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    tstyles_fuzz::openSeriesFile("input.tif", tstyles_fuzz::asText(data, size));
    return 0;
}
