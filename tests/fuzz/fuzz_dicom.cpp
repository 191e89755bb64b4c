// Fuzz target: one DICOM file (input.dcm), classic or enhanced multi-frame, header through GDCM after
// our checks, then its pixels decoded (GDCM's codecs: RLE, deflate, JPEG ...) and rescaled. Read in a
// reader process, as the program reads it: Debian's GDCM aborts on assertions in some damaged files
// (docs/readers/dicom.md), which the program reports as an InputError; so does this target.
#include "fuzz_series_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    tstyles_fuzz::openSeriesFileIsolated("input.dcm", tstyles_fuzz::asText(data, size));
    return 0;
}
