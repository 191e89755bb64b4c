// NIfTI-1 and NIfTI-2 images (.nii, .nii.gz; .hdr/.img pairs too) through Debian's libnifti2: a 3D
// image is one time-step, a 4D image a series along its fourth axis (time = toffset + index * TR),
// placed by the sform, else the qform, else the voxel sizes.
#pragma once

#include <filesystem>

#include "../source_series.h"

namespace tstyles {

SourceSeries openNifti(const std::filesystem::path& file);

// True when the file starts with a NIfTI-1 or NIfTI-2 header (either byte order; gzip is opened).
bool hasNiftiSignature(const std::filesystem::path& file);

}  // namespace tstyles
