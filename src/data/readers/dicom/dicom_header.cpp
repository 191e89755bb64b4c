// One file's header through GDCM, read up to PixelData (the pixels are read per time-step later).
// Classic files give one frame from their top-level tags; enhanced (multi-frame) files give one per
// item of the Per-frame Functional Groups, falling back on the Shared Functional Groups.
#include "dicom_header.h"

#include <cmath>

#include <gdcmException.h>
#include <gdcmReader.h>
#include <gdcmTrace.h>
#include <gdcmTransferSyntax.h>

#include "dicom_byte_walk.h"
#include "dicom_elements.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/interval.h"

namespace tstyles {
namespace {

const gdcm::Tag kPixelData(0x7fe0, 0x0010);
const gdcm::Tag kSharedGroups(0x5200, 0x9229);
const gdcm::Tag kPerFrameGroups(0x5200, 0x9230);
const gdcm::Tag kGridFrameOffsets(0x3004, 0x000c);
const gdcm::Tag kDoseGridScaling(0x3004, 0x000e);

// Where an enhanced frame's macros are found: its own per-frame item first, then the shared one,
// then (for classic files, and tolerant writers) the top level.
struct FrameSources {
    const gdcm::DataSet* perFrame = nullptr;
    const gdcm::DataSet* shared = nullptr;
    const gdcm::DataSet& top;
    const DicomContext& context;
};

// The first item of the macro sequence `sequence` that holds `tag`, else the top level if it does.
const gdcm::DataSet* holderOf(const FrameSources& sources, const gdcm::Tag& sequence, const gdcm::Tag& tag,
                              std::vector<gdcm::DataSet>& scratch) {
    for (const gdcm::DataSet* group : {sources.perFrame, sources.shared}) {
        if (group == nullptr) continue;
        std::vector<gdcm::DataSet> items = dicomItems(*group, sequence, "functional group macro", 64, sources.context);
        if (!items.empty() && items.front().FindDataElement(tag)) {
            scratch.push_back(items.front());
            return &scratch.back();
        }
    }
    return sources.top.FindDataElement(tag) ? &sources.top : nullptr;
}

std::optional<std::vector<double>> frameNumbers(const FrameSources& sources, const gdcm::Tag& sequence,
                                                const gdcm::Tag& tag, const char* keyword, std::size_t count) {
    std::vector<gdcm::DataSet> scratch;
    scratch.reserve(2);
    const gdcm::DataSet* holder = holderOf(sources, sequence, tag, scratch);
    return holder ? dicomNumbers(*holder, tag, keyword, count, sources.context) : std::nullopt;
}

// A binary value (UL, FD) of the frame's macro `sequence`, read by `read`.
template <typename Read>
std::optional<double> frameBinary(const FrameSources& sources, const gdcm::Tag& sequence, const gdcm::Tag& tag,
                                  const char* keyword, Read read) {
    std::vector<gdcm::DataSet> scratch;
    scratch.reserve(2);
    const gdcm::DataSet* holder = holderOf(sources, sequence, tag, scratch);
    return holder ? read(*holder, tag, keyword, sources.context) : std::nullopt;
}

std::optional<std::string> frameText(const FrameSources& sources, const gdcm::Tag& sequence, const gdcm::Tag& tag) {
    std::vector<gdcm::DataSet> scratch;
    scratch.reserve(2);
    const gdcm::DataSet* holder = holderOf(sources, sequence, tag, scratch);
    return holder ? dicomText(*holder, tag) : std::nullopt;
}

// The acquisition moment: the frame's or file's date-time, else date and time, else content time.
std::optional<double> acquiredSeconds(const FrameSources& sources) {
    const DicomContext& context = sources.context;
    const gdcm::Tag frameDateTime(0x0018, 0x9074), dateTime(0x0008, 0x002a);
    if (auto text = frameText(sources, gdcm::Tag(0x0020, 0x9111), frameDateTime))
        return dicomDateTimeSeconds(*text, frameDateTime, "FrameAcquisitionDateTime", context);
    if (auto text = dicomText(sources.top, dateTime))
        return dicomDateTimeSeconds(*text, dateTime, "AcquisitionDateTime", context);
    const std::pair<gdcm::Tag, gdcm::Tag> dateAndTime[] = {{gdcm::Tag(0x0008, 0x0022), gdcm::Tag(0x0008, 0x0032)},
                                                           {gdcm::Tag(0x0008, 0x0023), gdcm::Tag(0x0008, 0x0033)}};
    const char* timeNames[] = {"AcquisitionTime", "ContentTime"};
    for (int which = 0; which < 2; ++which) {
        const auto time = dicomText(sources.top, dateAndTime[which].second);
        if (!time) continue;
        double seconds = dicomTimeSeconds(*time, dateAndTime[which].second, timeNames[which], context);
        if (const auto date = dicomText(sources.top, dateAndTime[which].first))
            seconds += dicomDateSeconds(*date, dateAndTime[which].first, "AcquisitionDate", context);
        return seconds;
    }
    return std::nullopt;
}

std::optional<double> firstOf(const std::optional<std::vector<double>>& numbers) {
    return numbers ? std::optional<double>(numbers->front()) : std::nullopt;
}

DicomFrame readFrame(const FrameSources& sources, std::size_t index) {
    DicomFrame frame;
    frame.file = sources.context.file;
    frame.frameInFile = index;
    if (auto position = frameNumbers(sources, gdcm::Tag(0x0020, 0x9113), gdcm::Tag(0x0020, 0x0032),
                                     "ImagePositionPatient", 3))
        frame.position = glm::dvec3((*position)[0], (*position)[1], (*position)[2]);
    if (auto cosines = frameNumbers(sources, gdcm::Tag(0x0020, 0x9116), gdcm::Tag(0x0020, 0x0037),
                                    "ImageOrientationPatient", 6)) {
        frame.orientation.emplace();
        for (std::size_t i = 0; i < 6; ++i) (*frame.orientation)[i] = (*cosines)[i];
    }
    if (auto spacing = frameNumbers(sources, gdcm::Tag(0x0028, 0x9110), gdcm::Tag(0x0028, 0x0030), "PixelSpacing", 2))
        frame.pixelSpacing = std::array<double, 2>{(*spacing)[0], (*spacing)[1]};
    const gdcm::Tag transformation(0x0028, 0x9145);
    const gdcm::Tag slopeTag(0x0028, 0x1053);
    const gdcm::Tag interceptTag(0x0028, 0x1052);
    const std::optional<double> slope = firstOf(frameNumbers(sources, transformation, slopeTag, "RescaleSlope", 1));
    const std::optional<double> intercept =
        firstOf(frameNumbers(sources, transformation, interceptTag, "RescaleIntercept", 1));
    // The two come together (type 1C); GDCM asserts on an intercept without a slope, and a slope of 0
    // would read every pixel as the intercept.
    if (intercept && !slope)
        throwInputError(sources.context.file, dicomTagName(slopeTag, "RescaleSlope"),
                        "is missing, though RescaleIntercept (0028,1052) is given: the two come together");
    if (slope && *slope == 0.0)
        throwInputError(sources.context.file, dicomTagName(slopeTag, "RescaleSlope"),
                        "is 0: every pixel would read as the intercept; the stored values need a slope other than 0");
    // RT Dose scales its stored values to dose by DoseGridScaling instead.
    const std::optional<double> doseScaling =
        slope ? std::nullopt : dicomNumber(sources.top, kDoseGridScaling, "DoseGridScaling", sources.context);
    if (doseScaling && !(*doseScaling > 0.0))
        throwInputError(sources.context.file, dicomTagName(kDoseGridScaling, "DoseGridScaling"),
                        "is " + formatNumber(*doseScaling) + ": the dose per stored value must be above 0");
    frame.rescaleSlope = slope.value_or(doseScaling.value_or(1.0));
    frame.slopeIsDoseScaling = doseScaling.has_value();
    frame.rescaleIntercept = intercept.value_or(0.0);
    frame.temporalPosition = frameBinary(sources, gdcm::Tag(0x0020, 0x9111), gdcm::Tag(0x0020, 0x9128),
                                         "TemporalPositionIndex", dicomUnsignedLong);
    if (!frame.temporalPosition)
        frame.temporalPosition = dicomNumber(sources.top, gdcm::Tag(0x0020, 0x0100), "TemporalPositionIdentifier",
                                             sources.context);
    frame.triggerTimeMs = frameBinary(sources, gdcm::Tag(0x0018, 0x9118), gdcm::Tag(0x0020, 0x9153),
                                      "NominalCardiacTriggerDelayTime", dicomFloat64);
    if (!frame.triggerTimeMs)
        frame.triggerTimeMs = dicomNumber(sources.top, gdcm::Tag(0x0018, 0x1060), "TriggerTime", sources.context);
    frame.acquiredSeconds = acquiredSeconds(sources);
    frame.instanceNumber = dicomNumber(sources.top, gdcm::Tag(0x0020, 0x0013), "InstanceNumber", sources.context);
    return frame;
}

std::uint16_t requiredShort(const gdcm::DataSet& data, std::uint16_t element, const char* keyword,
                            const DicomContext& context) {
    const gdcm::Tag tag(0x0028, element);
    const auto value = dicomUnsignedShort(data, tag, keyword, context);
    if (!value) throwInputError(context.file, dicomTagName(tag, keyword), "is missing: an image needs it");
    return *value;
}

void readPixelFormat(const gdcm::DataSet& data, const DicomContext& context, DicomImageFile& image) {
    image.rows = requiredShort(data, 0x0010, "Rows", context);
    image.columns = requiredShort(data, 0x0011, "Columns", context);
    image.samplesPerPixel = dicomUnsignedShort(data, gdcm::Tag(0x0028, 0x0002), "SamplesPerPixel", context).value_or(1);
    image.bitsAllocated = requiredShort(data, 0x0100, "BitsAllocated", context);
    image.bitsStored = dicomUnsignedShort(data, gdcm::Tag(0x0028, 0x0101), "BitsStored", context)
                           .value_or(image.bitsAllocated);
    image.pixelRepresentation = requiredShort(data, 0x0103, "PixelRepresentation", context);
    image.photometric = dicomText(data, gdcm::Tag(0x0028, 0x0004)).value_or("MONOCHROME2");
}

// RT Dose (and some NM) files place their frames along the slice normal (row x column cosines) by
// GridFrameOffsetVector (PS3.3 C.8.8.3.2): offsets from the first frame where the first is 0,
// else, for the axial orientation 1\0\0\0\1\0 only, the frames' z coordinates.
void placeFramesByOffsets(const DicomFrame& first, std::size_t frames, const gdcm::DataSet& data,
                          const DicomContext& context, DicomImageFile& image) {
    const std::string field = dicomTagName(kGridFrameOffsets, "GridFrameOffsetVector");
    std::vector<double> offsets = *dicomNumbers(data, kGridFrameOffsets, "GridFrameOffsetVector", frames, context);
    if (!first.position || !first.orientation)
        throwInputError(context.file, field,
                        std::string("places frames from the first one's ImagePositionPatient (0020,0032) and "
                                    "ImageOrientationPatient (0020,0037), and this file lacks ") +
                            (first.position ? "the orientation" : "the position"));
    const std::array<double, 6>& cosines = *first.orientation;
    const glm::dvec3 normal = glm::normalize(
        glm::cross(glm::dvec3(cosines[0], cosines[1], cosines[2]), glm::dvec3(cosines[3], cosines[4], cosines[5])));
    const glm::dvec3 origin = *first.position;
    if (offsets.front() == 0.0) {
        image.framePlacement = "frames placed by GridFrameOffsetVector (3004,000C), offsets from the first frame";
    } else {
        const std::array<double, 6> axial{1, 0, 0, 0, 1, 0};
        bool isAxial = true;
        for (std::size_t i = 0; i < 6; ++i) isAxial = isAxial && std::abs(cosines[i] - axial[i]) < 1e-6;
        if (!isAxial || std::abs(offsets.front() - origin.z) > 1e-3)
            throwInputError(context.file, field,
                            "starts at " + formatNumber(offsets.front()) +
                                ": offsets start at 0 (from the first frame), or at the first frame's z (" +
                                formatNumber(origin.z) + ") where the orientation is axial (1\\0\\0\\0\\1\\0)");
        for (double& offset : offsets) offset -= origin.z;
        image.framePlacement = "frames placed by GridFrameOffsetVector (3004,000C), z coordinates";
    }
    for (std::size_t index = 0; index < frames; ++index) {
        DicomFrame frame = first;
        frame.frameInFile = index;
        frame.position = origin + normal * offsets[index];
        image.frames.push_back(frame);
    }
}

void readFrames(const gdcm::DataSet& data, const DicomContext& context, DicomImageFile& image) {
    const gdcm::Tag frameCountTag(0x0028, 0x0008);
    const double frameCount = dicomNumber(data, frameCountTag, "NumberOfFrames", context).value_or(1.0);
    if (!(frameCount >= 1.0) || frameCount != std::floor(frameCount) || frameCount > double(kMaxDicomFrames))
        throwInputError(context.file, dicomTagName(frameCountTag, "NumberOfFrames"),
                        "must be a whole number from 1 to " + std::to_string(kMaxDicomFrames));
    const std::size_t frames = std::size_t(frameCount);
    const std::vector<gdcm::DataSet> shared = dicomItems(data, kSharedGroups, "SharedFunctionalGroupsSequence", 1, context);
    const std::vector<gdcm::DataSet> perFrame =
        dicomItems(data, kPerFrameGroups, "PerFrameFunctionalGroupsSequence", kMaxDicomFrames, context);
    if (!perFrame.empty() && perFrame.size() != frames)
        throwInputError(context.file, dicomTagName(kPerFrameGroups, "PerFrameFunctionalGroupsSequence"),
                        "holds " + std::to_string(perFrame.size()) + " items for " + std::to_string(frames) + " frames");
    if (frames > 1 && perFrame.empty()) {
        if (!data.FindDataElement(kGridFrameOffsets))
            throwInputError(context.file, dicomTagName(kPerFrameGroups, "PerFrameFunctionalGroupsSequence"),
                            "is missing: the " + std::to_string(frames) +
                                " frames of this multi-frame file have no positions of their own, and no "
                                "GridFrameOffsetVector (3004,000C) places them");
        const FrameSources sources{nullptr, shared.empty() ? nullptr : &shared.front(), data, context};
        placeFramesByOffsets(readFrame(sources, 0), frames, data, context, image);
        return;
    }
    for (std::size_t index = 0; index < frames; ++index) {
        const FrameSources sources{perFrame.empty() ? nullptr : &perFrame[index],
                                   shared.empty() ? nullptr : &shared.front(), data, context};
        image.frames.push_back(readFrame(sources, index));
    }
}

// The tags that make two series different images of the patient rather than the same image taken
// again: their texts as given (an absent tag is left out). Time tags are not among them.
std::string acquisitionParametersOf(const gdcm::DataSet& data) {
    struct Parameter {
        std::uint16_t group, element;
        const char* keyword;
    };
    static constexpr Parameter kParameters[] = {
        {0x0008, 0x0008, "ImageType"},        {0x0018, 0x0020, "ScanningSequence"},
        {0x0018, 0x0021, "SequenceVariant"},  {0x0018, 0x0024, "SequenceName"},
        {0x0018, 0x0050, "SliceThickness"},   {0x0018, 0x0060, "KVP"},
        {0x0018, 0x0080, "RepetitionTime"},   {0x0018, 0x0081, "EchoTime"},
        {0x0018, 0x0082, "InversionTime"},    {0x0018, 0x0087, "MagneticFieldStrength"},
        {0x0018, 0x1030, "ProtocolName"},     {0x0018, 0x1210, "ConvolutionKernel"},
        {0x0018, 0x1314, "FlipAngle"},        {0x0028, 0x0030, "PixelSpacing"},
    };
    std::string text;
    for (const Parameter& parameter : kParameters)
        if (const auto value = dicomText(data, gdcm::Tag(parameter.group, parameter.element)))
            text += std::string(text.empty() ? "" : "; ") + parameter.keyword + "=" + *value;
    return text;
}

DicomImageFile headerOf(const gdcm::File& parsed, const std::filesystem::path& file) {
    const gdcm::TransferSyntax syntax = parsed.GetHeader().GetDataSetTransferSyntax();
    const DicomContext context{file, syntax.GetSwapCode() == gdcm::SwapCode::BigEndian};
    const gdcm::DataSet& data = parsed.GetDataSet();

    DicomImageFile image;
    image.file = file;
    image.transferSyntax = syntax.GetString() ? syntax.GetString() : "";
    image.compressed = syntax.IsEncapsulated();
    image.deflated = syntax == gdcm::TransferSyntax::DeflatedExplicitVRLittleEndian;
    image.seriesUid = dicomText(data, gdcm::Tag(0x0020, 0x000e)).value_or("");
    image.seriesNumber = dicomNumber(data, gdcm::Tag(0x0020, 0x0011), "SeriesNumber", context);
    image.seriesDescription = dicomText(data, gdcm::Tag(0x0008, 0x103e)).value_or("");
    image.modality = dicomText(data, gdcm::Tag(0x0008, 0x0060)).value_or("");
    image.frameOfReference = dicomText(data, gdcm::Tag(0x0020, 0x0052)).value_or("");
    image.acquisitionParameters = acquisitionParametersOf(data);
    image.rescaleType = dicomText(data, gdcm::Tag(0x0028, 0x1054)).value_or("");
    // RT Dose says its unit in DoseUnits: GY (gray), or RELATIVE (to an unstated reference: no unit).
    if (image.rescaleType.empty() && dicomText(data, gdcm::Tag(0x3004, 0x0002)) == "GY") image.rescaleType = "Gy";
    // Rows is what every image has and nothing else: files without it (reports, DICOMDIR) hold no frames.
    if (!data.FindDataElement(gdcm::Tag(0x0028, 0x0010))) return image;
    readPixelFormat(data, context, image);
    readFrames(data, context, image);
    return image;
}

}  // namespace

void silenceGdcm() {
    // GDCM's trace switches are its own process-wide settings; set once, before the first read.
    static const bool silenced = [] {
        gdcm::Trace::SetDebug(false);
        gdcm::Trace::SetWarning(false);
        gdcm::Trace::SetError(false);
        return true;
    }();
    (void)silenced;
}

DicomImageFile readDicomHeader(const std::filesystem::path& file) {
    requireRegularFile(file, "DICOM file");
    silenceGdcm();
    requireWholeDicomFile(file);
    gdcm::Reader reader;
    reader.SetFileName(file.c_str());
    // PixelData itself is skipped: the stream stops where its value starts, nothing of it is read.
    if (!reader.ReadUpToTag(kPixelData, {kPixelData}))
        throwInputError(file, "", "is not a readable DICOM file (GDCM cannot parse its header: damaged or truncated?)");
    // GDCM throws its own exceptions on some damaged sequences: the file is bad input like any other.
    try {
        DicomImageFile image = headerOf(reader.GetFile(), file);
        image.pixelDataOffset = reader.GetStreamCurrentPosition();
        return image;
    } catch (const gdcm::Exception& error) {
        throwInputError(file, "", std::string("is a damaged DICOM file (GDCM: ") + error.GetDescription() + ")");
    }
}

}  // namespace tstyles
