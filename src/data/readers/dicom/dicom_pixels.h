// The pixels of DICOM frames: which pixel formats are read (one sample, MONOCHROME1/2, 8, 16 or 32
// bits, signed or not), and one file's frames decoded through GDCM (every transfer syntax GDCM
// decodes: JPEG, JPEG-LS, JPEG 2000, RLE, deflate) into floats after the rescale.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "dicom_header.h"

namespace tstyles {

// An InputError naming the file and the tag unless its pixels are a format we read.
void requireSupportedPixels(const DicomImageFile& image);

// A file's decoded pixel buffer, every frame, as GDCM gives it (host byte order).
struct DicomPixelBuffer {
    std::filesystem::path file;
    std::vector<char> bytes;
    std::uint16_t bitsAllocated = 16;
    std::uint16_t bitsStored = 16;
    bool isSigned = false;
};

// Decodes the file's pixel data; its size must match the header and fit under `memoryCap` (checked
// before anything is allocated for it). A file GDCM cannot decode (truncated, damaged) is an
// InputError naming it.
DicomPixelBuffer readDicomPixels(const DicomImageFile& image, std::uint64_t memoryCap);

// Frame `frame.frameInFile` of the buffer, rescaled, into `out` (columns x rows floats).
void decodeDicomFrame(const DicomPixelBuffer& pixels, const DicomImageFile& image, const DicomFrame& frame, float* out);

}  // namespace tstyles
