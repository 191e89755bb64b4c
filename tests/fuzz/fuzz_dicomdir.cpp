// Fuzz target: a DICOMDIR (a CD or USB export's directory) through GDCM after our checks: its
// directory records, the ReferencedFileIDs matched without regard to case, refused where they
// climb out of the folder or name no file. In a reader process, as the program reads DICOM.
#include "fuzz_series_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    tstyles_fuzz::openSeriesFileIsolated("DICOMDIR", tstyles_fuzz::asText(data, size));
    return 0;
}
