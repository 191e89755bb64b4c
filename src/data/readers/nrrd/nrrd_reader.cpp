// From a NRRD header to time-steps: which axis is time, the spatial frame, and strided reads.
#include "nrrd_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <memory>
#include <set>

#include "../infinite_values.h"
#include "nrrd_header.h"
#include "../oriented_axes.h"
#include "../file_bytes.h"
#include "tstyles/core/ascii_case.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

// Kinds that say an axis holds the components of one sample, not a sequence in time.
bool isComponentKind(const std::string& kind) {
    static const std::set<std::string> components = {
        "vector", "covariant-vector", "normal", "stub", "scalar", "complex", "2-vector", "3-color",
        "RGB-color", "HSV-color", "XYZ-color", "4-color", "RGBA-color", "3-vector", "3-gradient",
        "3-normal", "4-vector", "quaternion", "2D-symmetric-matrix", "2D-masked-symmetric-matrix",
        "2D-matrix", "2D-masked-matrix", "3D-symmetric-matrix", "3D-masked-symmetric-matrix",
        "3D-matrix", "3D-masked-matrix"};
    return components.count(kind) > 0;
}

// The non-spatial axis of a 4D NRRD: the one without a space direction, else the one of kind
// "time", else the last (slowest) axis.
int findTimeAxis(const NrrdHeader& header) {
    if (header.dimension == 3) return -1;
    const bool hasDirections =
        std::any_of(header.directions.begin(), header.directions.end(), [](const auto& d) { return d.has_value(); });
    int timeAxis = 3;
    if (hasDirections) {
        const auto none = std::count_if(header.directions.begin(), header.directions.end(),
                                        [](const auto& d) { return !d.has_value(); });
        if (none != 1)
            throwInputError(header.headerFile, "space directions",
                            "a 4D NRRD needs exactly one axis without a direction (the time axis), found " +
                                std::to_string(none));
        timeAxis = int(std::find_if(header.directions.begin(), header.directions.end(),
                                    [](const auto& d) { return !d.has_value(); }) -
                       header.directions.begin());
    } else {
        const auto time = std::find(header.kinds.begin(), header.kinds.end(), "time");
        if (time != header.kinds.end()) timeAxis = int(time - header.kinds.begin());
    }
    const std::string& kind = header.kinds[std::size_t(timeAxis)];
    if (isComponentKind(kind))
        throwInputError(header.headerFile, "kinds",
                        "axis " + std::to_string(timeAxis) + " is of kind \"" + kind +
                            "\": multi-component samples are not supported, only a time axis");
    return timeAxis;
}

struct NrrdLayout {
    std::array<int, 3> spatialAxes{0, 1, 2};
    int timeAxis = -1;
    std::vector<std::size_t> strides;  // in values, per file axis
    std::size_t totalValues = 1;
};

NrrdLayout layoutOf(const NrrdHeader& header) {
    NrrdLayout layout;
    layout.timeAxis = findTimeAxis(header);
    int next = 0;
    for (int axis = 0; axis < header.dimension; ++axis)
        if (axis != layout.timeAxis) layout.spatialAxes[std::size_t(next++)] = axis;
    double values = 1.0;
    for (std::int64_t size : header.sizes) values *= double(size);
    // Each size is at most 10^6, but four of them multiply past any file and past size_t.
    if (values > 1e15)
        throwInputError(header.headerFile, "sizes", "describe " + std::to_string(std::uint64_t(values)) +
                                                        " values, more than any volume series can hold");
    for (std::int64_t size : header.sizes) {
        layout.strides.push_back(layout.totalValues);
        layout.totalValues *= std::size_t(size);
    }
    for (int axis : layout.spatialAxes)
        if (header.sizes[std::size_t(axis)] < 2)
            throwInputError(header.headerFile, "sizes",
                            "spatial axis " + std::to_string(axis) + " has " +
                                std::to_string(header.sizes[std::size_t(axis)]) +
                                " sample: each spatial axis needs at least 2");
    return layout;
}

// The placement and spacing of the spatial axes.
OrientedAxes frameOf(const NrrdHeader& header, const NrrdLayout& layout, const glm::ivec3& dims) {
    std::array<glm::dvec3, 3> axes{};
    bool directed = false;
    for (std::size_t index = 0; index < 3; ++index) {
        const auto axis = std::size_t(layout.spatialAxes[index]);
        if (header.directions[axis]) {
            axes[index] = *header.directions[axis];
            directed = true;
        } else {
            const double spacing = std::isnan(header.spacings[axis]) ? 1.0 : std::abs(header.spacings[axis]);
            axes[index] = glm::dvec3(0.0);
            axes[index][int(index)] = spacing;
        }
    }
    const glm::dvec3 origin = directed ? header.origin.value_or(glm::dvec3(0.0)) : glm::dvec3(0.0);
    return orientAxes(origin, axes, dims, header.headerFile, directed ? "space directions" : "spacings");
}

double stepTime(const NrrdHeader& header, int timeAxis, std::size_t index) {
    if (timeAxis < 0) return 0.0;
    const double first = std::isnan(header.axisMins[std::size_t(timeAxis)]) ? 0.0 : header.axisMins[std::size_t(timeAxis)];
    const double spacing = header.spacings[std::size_t(timeAxis)];
    return first + double(index) * (std::isnan(spacing) || spacing <= 0.0 ? 1.0 : spacing);
}

// The world axes' meaning from the `space` field (anatomical spaces only) and `space units`.
std::array<SpatialAxis, 3> nrrdAxes(const NrrdHeader& header) {
    using D = AxisDirection;
    struct Space {
        const char* name;
        const char* abbreviation;
        std::array<D, 3> directions;
    };
    static constexpr Space kSpaces[] = {
        {"right-anterior-superior", "ras", {D::Right, D::Anterior, D::Superior}},
        {"left-anterior-superior", "las", {D::Left, D::Anterior, D::Superior}},
        {"left-posterior-superior", "lps", {D::Left, D::Posterior, D::Superior}},
    };
    const std::string space = asciiLowercase(header.space);
    std::array<SpatialAxis, 3> axes;
    for (const Space& known : kSpaces)
        if (space == known.name || space == known.abbreviation)
            for (std::size_t axis = 0; axis < 3; ++axis) axes[axis].direction = known.directions[axis];
    if (header.spaceUnits.size() == 3)
        for (std::size_t axis = 0; axis < 3; ++axis) axes[axis].unit = header.spaceUnits[axis];
    return axes;
}

// Where the data starts, once it is known to be in the file, before anything is allocated for it
// ("byte skip: -1": the data is the file's last bytes). A raw file cut short names the first
// time-step it lacks.
std::uint64_t checkedDataOffset(const NrrdHeader& header, const NrrdLayout& layout, std::uint64_t stepBytes) {
    const double totalBytes = double(layout.totalValues) * double(bytesPerValue(header.type));
    const std::uint64_t size = regularFileSize(header.dataFile, "NRRD data file");
    if (header.dataAtEnd && totalBytes > double(size))
        throwInputError(header.dataFile, "",
                        "is truncated: the NRRD data needs " + std::to_string(std::uint64_t(totalBytes)) +
                            " bytes, the file has only " + std::to_string(size));
    const std::uint64_t offset = header.dataAtEnd ? size - std::uint64_t(totalBytes) : header.dataOffset;
    const std::uint64_t available = size > offset ? size - offset : 0;
    if (header.encoding == DataEncoding::Raw && layout.timeAxis == 3 && double(available) < totalBytes) {
        const std::uint64_t step = available / stepBytes;
        throwInputError(header.dataFile, "",
                        "is truncated: time-step " + std::to_string(step) + " of " +
                            std::to_string(header.sizes[3]) + " of the NRRD data needs " + std::to_string(stepBytes) +
                            " bytes from byte " + std::to_string(offset + step * stepBytes) + ", the file has only " +
                            std::to_string(available - step * stepBytes));
    }
    requireDataInFile(header.dataFile, offset, totalBytes, header.encoding, "the NRRD data");
    return offset;
}

}  // namespace

SourceSeries openNrrd(const std::filesystem::path& file) {
    const NrrdHeader header = readNrrdHeader(file);
    const NrrdLayout layout = layoutOf(header);
    glm::ivec3 dims;
    for (int index = 0; index < 3; ++index) dims[index] = int(header.sizes[std::size_t(layout.spatialAxes[std::size_t(index)])]);
    const OrientedAxes frame = frameOf(header, layout, dims);
    const std::size_t stepCount = layout.timeAxis < 0 ? 1 : std::size_t(header.sizes[std::size_t(layout.timeAxis)]);
    const std::size_t valueBytes = bytesPerValue(header.type);
    const std::size_t stepValues = std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
    const std::uint64_t dataOffset = checkedDataOffset(header, layout, stepValues * valueBytes);

    SourceSeries source;
    source.name = file.stem().string();
    source.file = file;
    source.format = "NRRD";
    source.axes = nrrdAxes(header);
    for (std::size_t index = 0; index < stepCount; ++index) {
        SourceStep step;
        step.time = stepTime(header, layout.timeAxis, index);
        RectilinearGrid grid;
        grid.dims = dims;
        grid.spacing = frame.spacing;
        step.grid = grid;
        step.placement = frame.placement;
        step.type = header.type;
        step.file = header.dataFile;
        source.steps.push_back(step);
    }

    // A raw file whose time axis is the slowest is read one time-step at a time; anything else is
    // read whole, once, on the first step asked for.
    const bool sliceable = header.encoding == DataEncoding::Raw && (layout.timeAxis < 0 || layout.timeAxis == 3);
    auto whole = std::make_shared<std::vector<std::uint8_t>>();
    source.readStep = [header, layout, dims, frame, sliceable, whole, dataOffset, valueBytes,
                       stepValues](std::size_t index) {
        std::vector<float> values;
        if (sliceable) {
            const auto bytes = readDataBytes(header.dataFile, dataOffset + index * stepValues * valueBytes,
                                             stepValues * valueBytes, DataEncoding::Raw,
                                             "time-step " + std::to_string(index) + " of the NRRD data");
            values = decodeValues(bytes.data(), stepValues, header.type, header.byteOrder);
        } else {
            if (whole->empty())
                *whole = readDataBytes(header.dataFile, dataOffset, layout.totalValues * valueBytes, header.encoding,
                                       "the NRRD data");
            values.resize(stepValues);
            const std::size_t base = layout.timeAxis < 0 ? 0 : index * layout.strides[std::size_t(layout.timeAxis)];
            const std::size_t sx = layout.strides[std::size_t(layout.spatialAxes[0])];
            const std::size_t sy = layout.strides[std::size_t(layout.spatialAxes[1])];
            const std::size_t sz = layout.strides[std::size_t(layout.spatialAxes[2])];
            std::size_t out = 0;
            for (int z = 0; z < dims.z; ++z)
                for (int y = 0; y < dims.y; ++y)
                    for (int x = 0; x < dims.x; ++x)
                        values[out++] = float(decodeValue(
                            whole->data() + (base + std::size_t(x) * sx + std::size_t(y) * sy + std::size_t(z) * sz) * valueBytes,
                            header.type, header.byteOrder));
        }
        refuseInfinities(values, dims, header.dataFile, index);
        if (frame.mirrorX) mirrorAlongX(values, dims);
        return values;
    };
    return source;
}

}  // namespace tstyles
