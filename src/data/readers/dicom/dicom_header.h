// What one DICOM file says before its pixels are read: its series, image size and pixel format,
// and per frame (one for a classic file, NumberOfFrames for an enhanced one) where the slice lies
// in the patient (LPS, mm), its rescale and its time tags.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tstyles {

// Most frames one enhanced file may declare before its pixels are looked at.
inline constexpr std::size_t kMaxDicomFrames = 65536;

struct DicomFrame {
    std::filesystem::path file;
    std::size_t frameInFile = 0;
    // Absent in images that are not slices of a volume (screenshots, scouts of other series): only
    // the chosen series must have them.
    std::optional<glm::dvec3> position;               // ImagePositionPatient: the first pixel's centre, LPS mm
    std::optional<std::array<double, 6>> orientation; // ImageOrientationPatient: row then column cosines
    std::optional<std::array<double, 2>> pixelSpacing;// PixelSpacing: between rows, then between columns (mm)
    double rescaleSlope = 1.0;
    double rescaleIntercept = 0.0;
    bool slopeIsDoseScaling = false;         // RT Dose's DoseGridScaling (3004,000E) gave the slope
    std::optional<double> temporalPosition;  // TemporalPositionIdentifier, or TemporalPositionIndex
    std::optional<double> triggerTimeMs;     // TriggerTime, or NominalCardiacTriggerDelayTime
    std::optional<double> acquiredSeconds;   // AcquisitionDateTime, (AcquisitionDate +) AcquisitionTime, or ContentTime
    std::optional<double> instanceNumber;    // InstanceNumber: the last tie-breaker
};

struct DicomImageFile {
    std::filesystem::path file;
    std::string seriesUid;          // SeriesInstanceUID; empty when the file has none
    std::optional<double> seriesNumber;
    std::string seriesDescription;
    std::string modality;
    std::string frameOfReference;   // FrameOfReferenceUID: series that share it share the patient frame
    // The acquisition parameters that tell one kind of image from another (TR, TE, flip angle,
    // sequence; kVp, kernel; slice thickness ...), as "keyword=value" texts: series with equal ones
    // were acquired alike, so phases of one study can be read as time-steps (dicom_phases.h).
    std::string acquisitionParameters;
    std::string rescaleType;        // RescaleType ("HU", "US" ...), where given
    std::string photometric;        // PhotometricInterpretation
    std::string transferSyntax;     // its UID
    bool compressed = false;        // an encapsulated (compressed) transfer syntax
    bool deflated = false;          // the whole data set deflated: file offsets say nothing of the pixels
    std::uint64_t pixelDataOffset = 0;  // where PixelData's value starts in the file
    std::uint16_t rows = 0;
    std::uint16_t columns = 0;
    std::uint16_t samplesPerPixel = 1;
    std::uint16_t bitsAllocated = 0;
    std::uint16_t bitsStored = 0;
    std::uint16_t pixelRepresentation = 0;  // 0 unsigned, 1 two's complement
    std::vector<DicomFrame> frames;         // empty: not an image (a report, a DICOMDIR)
    // How the frames of a multi-frame file without per-frame positions were placed (RT Dose's
    // GridFrameOffsetVector), for `info`; empty where each frame has its own.
    std::string framePlacement;
};

// Reads the header (everything before PixelData) through GDCM. Not a DICOM file, or a damaged or
// contradictory header, is an InputError naming the file and the tag.
DicomImageFile readDicomHeader(const std::filesystem::path& file);

// Switches GDCM's own messages off (once per process): ours say what went wrong.
void silenceGdcm();

}  // namespace tstyles
