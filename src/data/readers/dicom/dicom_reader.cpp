// From files to a SourceSeries: headers read once, the series chosen and stacked, the patient's LPS
// frame turned into our RAS world; readStep decodes one time-step's files at a time.
#include "dicom_reader.h"

#include <map>
#include <memory>
#include <sstream>

#include "dicom_directory.h"
#include "dicom_files.h"
#include "dicom_phases.h"
#include "dicom_pixels.h"
#include "dicom_series.h"
#include "dicom_volumes.h"
#include "../infinite_values.h"
#include "../oriented_axes.h"
#include "../series_assembly.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/data/reading_monitor.h"

namespace tstyles {
namespace {

struct DicomInputs {
    std::vector<DicomImageFile> headers;
    std::size_t skipped = 0;  // files in folders without the DICM magic
    std::vector<std::string> notes;  // what a DICOMDIR referenced
};

// GDCM, named to whoever watches the reading (reading_monitor.h): a crash inside it is GDCM's.
constexpr const char* kGdcm = "the DICOM library (GDCM)";

DicomImageFile headerOf(const std::filesystem::path& file, ReadingMonitor* monitor) {
    reportStage(monitor, file, kGdcm, "reading the header");
    return readDicomHeader(file);
}

DicomInputs readInputs(const std::vector<std::filesystem::path>& inputs, ReadingMonitor* monitor) {
    DicomInputs read;
    for (const std::filesystem::path& input : inputs) {
        std::error_code error;
        if (isDicomDirectoryFile(input) && !std::filesystem::is_directory(input, error)) {
            reportStage(monitor, input, kGdcm, "reading the DICOMDIR");
            const DicomDirectoryFiles directory = filesOfDicomDirectory(input);
            read.notes.push_back("DICOMDIR: " + std::to_string(directory.files.size()) + " files referenced by its " +
                                 std::to_string(directory.records) + " directory records");
            for (const auto& file : directory.files) read.headers.push_back(headerOf(file, monitor));
            continue;
        }
        if (!std::filesystem::is_directory(input, error)) {
            read.headers.push_back(headerOf(input, monitor));
            continue;
        }
        const DicomFileList list = dicomFilesUnder(input);
        read.skipped += list.skipped;
        for (const auto& file : list.files) read.headers.push_back(headerOf(file, monitor));
    }
    return read;
}

// CT values are Hounsfield units unless RescaleType says otherwise; "US" is "unspecified".
std::string valueUnitOf(const DicomImageFile& image) {
    if (!image.rescaleType.empty() && image.rescaleType != "US") return image.rescaleType;
    return image.modality == "CT" ? "HU" : "";
}

// DICOM's patient frame is LPS; ours, like NIfTI's, RAS: x and y change sign.
glm::dvec3 toRas(const glm::dvec3& lps) { return {-lps.x, -lps.y, lps.z}; }

OrientedAxes rasFrame(const DicomVolumes& volumes, const std::filesystem::path& file) {
    const double sliceStep = volumes.evenSlices ? volumes.sliceSpacing : 1.0;
    const std::array<glm::dvec3, 3> axes{toRas(volumes.directions[0] * volumes.pixelSpacing.x),
                                         toRas(volumes.directions[1] * volumes.pixelSpacing.y),
                                         toRas(volumes.directions[2] * sliceStep)};
    return orientAxes(toRas(volumes.origin), axes, volumes.dims, file, "(0020,0037) ImageOrientationPatient");
}

ValueType storedType(const DicomImageFile& image) {
    const bool isSigned = image.pixelRepresentation == 1;
    if (image.bitsAllocated == 8) return isSigned ? ValueType::Int8 : ValueType::UInt8;
    if (image.bitsAllocated == 16) return isSigned ? ValueType::Int16 : ValueType::UInt16;
    return isSigned ? ValueType::Int32 : ValueType::Float32;
}

std::vector<std::string> dicomReadingNotes(const std::vector<DicomSeriesEntry>& series, const DicomSeriesChoice& choice,
                                      const DicomInputs& inputs, const DicomVolumes& volumes) {
    std::vector<std::string> notes;
    for (std::size_t i = 0; i < series.size(); ++i)
        notes.push_back("DICOM " + series[i].describe(i + 1) + (choice.taken(i) ? " - taken (" + choice.why + ")" : ""));
    notes.insert(notes.end(), inputs.notes.begin(), inputs.notes.end());
    if (inputs.skipped > 0)
        notes.push_back(std::to_string(inputs.skipped) + " files without the DICM magic left out");
    notes.insert(notes.end(), volumes.notes.begin(), volumes.notes.end());
    const DicomImageFile& first = series[choice.indices.front()].files.front();
    if (!first.framePlacement.empty()) notes.push_back(first.framePlacement);
    notes.push_back("patient frame LPS turned to RAS (x toward the patient's right, y anterior, z superior), mm");
    std::ostringstream pixels;
    pixels << first.bitsStored << " of " << first.bitsAllocated << " bits, "
           << (first.pixelRepresentation == 1 ? "signed" : "unsigned")
           << (first.frames.front().slopeIsDoseScaling ? ", DoseGridScaling applied"
                                                        : ", RescaleSlope/RescaleIntercept applied");
    if (first.photometric == "MONOCHROME1")
        pixels << "; MONOCHROME1 (higher values shown darker on film): values kept as stored, not inverted";
    if (first.compressed) pixels << "; compressed transfer syntax " << first.transferSyntax << " decoded by GDCM";
    notes.push_back(pixels.str());
    return notes;
}

// What readStep needs: the chosen series' headers by file, and the stacked frames.
struct DicomStepSource {
    std::map<std::filesystem::path, DicomImageFile> headers;
    DicomVolumes volumes;
    bool mirrorX = false;
    std::uint64_t memoryCap = 0;
    ReadingMonitor* monitor = nullptr;  // lives as long as the reading that calls readStep
};

std::vector<float> readDicomStep(const DicomStepSource& source, std::size_t step) {
    const glm::ivec3 dims = source.volumes.dims;
    const std::size_t sliceSize = std::size_t(dims.x) * std::size_t(dims.y);
    std::vector<float> values(sliceSize * std::size_t(dims.z));
    // The slices of an enhanced file follow each other: its decoded buffer is kept while they do.
    DicomPixelBuffer pixels;
    for (std::size_t slice = 0; slice < std::size_t(dims.z); ++slice) {
        const DicomFrame& frame = source.volumes.steps[step][slice];
        const DicomImageFile& header = source.headers.at(frame.file);
        if (pixels.file != frame.file) {
            reportStage(source.monitor, frame.file, kGdcm, "decoding the pixels");
            pixels = readDicomPixels(header, source.memoryCap);
        }
        decodeDicomFrame(pixels, header, frame, values.data() + slice * sliceSize);
    }
    refuseInfinities(values, dims, source.volumes.steps[step].front().file, step);
    if (source.mirrorX) mirrorAlongX(values, dims);
    return values;
}

}  // namespace

SourceSeries openDicom(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options) {
    const std::filesystem::path& input = inputs.front();
    DicomInputs read = readInputs(inputs, options.monitor);
    const std::size_t fileCount = read.headers.size();
    std::vector<DicomSeriesEntry> series = groupDicomSeries(std::move(read.headers));
    if (series.empty())
        throwInputError(input, "", "holds no DICOM image series (" + std::to_string(fileCount) +
                                       " DICOM files, none with image pixels)");
    DicomSeriesChoice choice = chooseDicomSeries(series, options.seriesChoice, input);
    if (choice.indices.empty()) choice = defaultDicomChoice(series, input);
    for (std::size_t index : choice.indices)
        for (const DicomImageFile& file : series[index].files) requireSupportedPixels(file);

    auto stepSource = std::make_shared<DicomStepSource>();
    stepSource->volumes = choice.indices.size() == 1 ? stackDicomVolumes(series[choice.indices.front()], input)
                                                     : stackDicomPhases(series, choice, input);
    const DicomVolumes& volumes = stepSource->volumes;
    requireStepCount(input, "(0020,0100) TemporalPositionIdentifier", volumes.steps.size());
    const DicomImageFile& first = series[choice.indices.front()].files.front();
    const OrientedAxes frame = rasFrame(volumes, first.file);
    stepSource->mirrorX = frame.mirrorX;
    stepSource->memoryCap = memoryCap(options.maxMemoryBytes);
    stepSource->monitor = options.monitor;
    for (std::size_t index : choice.indices)
        for (const DicomImageFile& file : series[index].files) stepSource->headers.emplace(file.file, file);

    SourceSeries source;
    source.name = !first.seriesDescription.empty() ? first.seriesDescription : input.filename().string();
    if (choice.indices.size() > 1) {
        // Phases: every phase's description, in time order ("arterial, portal venous, delayed").
        std::string names;
        for (std::size_t index : choice.indices) {
            const std::string& description = series[index].files.front().seriesDescription;
            if (!description.empty()) names += (names.empty() ? "" : ", ") + description;
        }
        if (!names.empty()) source.name = names;
    }
    source.file = input;
    source.format = "DICOM";
    const AxisDirection directions[3] = {AxisDirection::Right, AxisDirection::Anterior, AxisDirection::Superior};
    for (int axis = 0; axis < 3; ++axis) source.axes[std::size_t(axis)] = {std::string(1, char('x' + axis)), "mm", directions[axis]};
    source.time.unit = volumes.timeUnit;
    source.valueUnit = valueUnitOf(first);
    source.notes = dicomReadingNotes(series, choice, read, volumes);
    for (std::size_t index = 0; index < volumes.steps.size(); ++index) {
        RectilinearGrid grid;
        grid.dims = volumes.dims;
        grid.spacing = frame.spacing;
        if (!volumes.evenSlices) grid.axisPositions[2] = volumes.sliceOffsets;
        SourceStep step;
        step.time = volumes.times[index];
        step.grid = grid;
        step.placement = frame.placement;
        step.type = storedType(first);
        step.file = volumes.steps[index].front().file;
        source.steps.push_back(step);
    }
    source.readStep = [stepSource](std::size_t step) { return readDicomStep(*stepSource, step); };
    return source;
}

}  // namespace tstyles
