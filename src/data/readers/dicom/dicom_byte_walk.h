// A walk over a DICOM file's element headers before GDCM reads it: every element's length must fit
// in the file. Debian's GDCM asserts (aborts the process) on a file cut inside its header; a cut
// file must be an InputError instead.
#pragma once

#include <filesystem>

namespace tstyles {

// An InputError naming the file and the element when one claims more bytes than the file has, or
// nesting is deeper than any real file's. Deflated data sets are not walked (GDCM inflates them).
void requireWholeDicomFile(const std::filesystem::path& file);

}  // namespace tstyles
