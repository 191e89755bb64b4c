// Fuzz target: a Hurricane Isabel raw file, plain or gzip (by its first two bytes), read as one
// hour of 6 x 5 x 4 values (--dims 6x5x4, as the CLI tests' samples).
#include "fuzz_series_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool gzip = size >= 2 && data[0] == 0x1f && data[1] == 0x8b;
    tstyles::ReadOptions options;
    options.rawDims = glm::ivec3(6, 5, 4);
    tstyles_fuzz::openSeriesFile(gzip ? "QCLOUDf01.bin.gz" : "QCLOUDf01.bin", tstyles_fuzz::asText(data, size), options);
    return 0;
}
