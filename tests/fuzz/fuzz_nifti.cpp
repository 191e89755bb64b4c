// Fuzz target: a NIfTI-1 or NIfTI-2 single file (.nii): header through libnifti after our checks,
// then the image data.
#include "fuzz_series_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    tstyles_fuzz::openSeriesFile("input.nii", tstyles_fuzz::asText(data, size));
    return 0;
}
