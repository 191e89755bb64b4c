// From an OME-Zarr store's multiscales to a SourceSeries: the level (the finest that fits memory
// unless --level says), the channel (--channel, default 0), the frame and the time stamps.
#include "ome_zarr_reader.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>

#include "../infinite_values.h"
#include "ome_multiscales.h"
#include "../series_assembly.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "zarr_volume.h"

namespace tstyles {
namespace {

// Each chunk read costs a file look-up: a series cut into millions of tiny chunks would take
// minutes of them. Any number of chunks of 64 values or more is read; smaller ones up to 2^16.
constexpr double kFewestValuesPerChunk = 64.0;
constexpr double kTinyChunksRead = double(1 << 16);

// Which array dimension is which: x, y, z, and the time and channel axes where the image has them.
struct OmeLayout {
    std::array<std::size_t, 3> space{};  // x, y, z
    std::optional<std::size_t> time;
    std::optional<std::size_t> channel;
};

std::string shortNumber(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

std::string axisNames(const OmeMultiscales& image) {
    std::string names;
    for (const OmeAxis& axis : image.axes) names += (names.empty() ? "" : ", ") + axis.name;
    return names;
}

// Space axes named x, y and z are those; otherwise the last is x, then y, then z (the spec's order).
OmeLayout layoutOf(const OmeMultiscales& image) {
    OmeLayout layout;
    std::vector<std::size_t> spatial;
    for (std::size_t index = 0; index < image.axes.size(); ++index) {
        const OmeAxis& axis = image.axes[index];
        std::optional<std::size_t>* single = axis.type == OmeAxisType::Time      ? &layout.time
                                             : axis.type == OmeAxisType::Channel ? &layout.channel
                                                                                 : nullptr;
        if (!single) {
            spatial.push_back(index);
        } else if (single->has_value()) {
            throwInputError(image.attributesFile, "multiscales[0].axes",
                            "(" + axisNames(image) + ") is an axis order that cannot be a volume over time: two " +
                                (axis.type == OmeAxisType::Time ? "time" : "channel") + " axes");
        } else {
            *single = index;
        }
    }
    if (spatial.size() != 3)
        throwInputError(image.attributesFile, "multiscales[0].axes",
                        "(" + axisNames(image) + ") is an axis order that cannot be a volume over time: it has " +
                            std::to_string(spatial.size()) + " space axes, a volume needs z, y and x");
    const auto named = [&](const char* name) -> std::optional<std::size_t> {
        for (std::size_t index : spatial)
            if (image.axes[index].name == name) return index;
        return std::nullopt;
    };
    if (named("x") && named("y") && named("z"))
        layout.space = {*named("x"), *named("y"), *named("z")};
    else
        layout.space = {spatial[2], spatial[1], spatial[0]};
    return layout;
}

std::string omeLengthUnit(const std::string& unit) {
    static const std::pair<const char*, const char*> kShort[] = {
        {"micrometer", "um"}, {"nanometer", "nm"}, {"millimeter", "mm"}, {"centimeter", "cm"},
        {"meter", "m"},       {"kilometer", "km"}, {"picometer", "pm"},  {"angstrom", "angstrom"}};
    for (const auto& [name, symbol] : kShort)
        if (unit == name) return symbol;
    return unit;
}

// OME's time units (UDUNITS names) as our TimeAxis: the ones it has, nanoseconds as microseconds;
// any other is kept as plain numbers, with a note.
TimeAxis omeTimeAxis(const std::string& unit, double& factor, std::vector<std::string>& notes) {
    static const std::pair<const char*, TimeUnit> kUnits[] = {
        {"microsecond", TimeUnit::Microseconds}, {"millisecond", TimeUnit::Milliseconds}, {"second", TimeUnit::Seconds},
        {"minute", TimeUnit::Minutes},           {"hour", TimeUnit::Hours},               {"day", TimeUnit::Days}};
    TimeAxis axis;
    factor = 1.0;
    for (const auto& [name, known] : kUnits)
        if (unit == name) axis.unit = known;
    if (unit == "nanosecond") {
        axis.unit = TimeUnit::Microseconds;
        factor = 1e-3;
    } else if (axis.unit == TimeUnit::None && !unit.empty()) {
        notes.push_back("time unit \"" + unit + "\" kept as plain numbers (known: nanosecond to day)");
    }
    return axis;
}

std::uint64_t stepVoxels(const ZarrArray& array, const OmeLayout& layout) {
    double voxels = 1.0;
    for (std::size_t axis : layout.space) voxels *= double(array.shape[axis]);
    return std::uint64_t(voxels);
}

double levelBytes(const ZarrArray& array, const OmeLayout& layout, const ReadOptions& options) {
    const std::size_t steps = layout.time ? std::size_t(array.shape[*layout.time]) : 1;
    return double(selectedSteps(options.steps, steps).size()) * double(stepVoxels(array, layout)) *
           double(sizeof(float) + bytesPerDensity(options.precision));
}

ZarrArray openLevel(const OmeMultiscales& image, std::size_t level, const OmeLayout& layout, std::uint64_t cap) {
    ZarrArray array = readZarrArray(image.store / image.levels[level].path, image.zarrFormat, cap);
    if (array.shape.size() != image.axes.size())
        throwInputError(array.metadataFile, "shape",
                        "has " + std::to_string(array.shape.size()) + " dimensions, the multiscales' axes (" +
                            axisNames(image) + ") " + std::to_string(image.axes.size()));
    if (layout.time) requireStepCount(array.metadataFile, "shape", array.shape[*layout.time]);
    for (std::size_t axis : layout.space)
        if (array.shape[axis] > std::uint64_t(std::numeric_limits<int>::max()))
            throwInputError(array.metadataFile, "shape",
                            "space axis \"" + image.axes[axis].name + "\" has " + std::to_string(array.shape[axis]) +
                                " samples, more than a volume can hold");
    for (std::size_t axis : layout.space)
        if (array.shape[axis] < 2)
            throwInputError(array.metadataFile, "shape",
                            "space axis \"" + image.axes[axis].name + "\" has " + std::to_string(array.shape[axis]) +
                                " sample: each space axis needs at least 2");
    return array;
}

std::string dimsText(const ZarrArray& array, const OmeLayout& layout) {
    return std::to_string(array.shape[layout.space[0]]) + " x " + std::to_string(array.shape[layout.space[1]]) + " x " +
           std::to_string(array.shape[layout.space[2]]);
}

// --level, else level 0, else the finest level that fits the memory cap (then noted).
std::size_t chooseLevel(const OmeMultiscales& image, const OmeLayout& layout, const ReadOptions& options,
                        std::vector<std::string>& notes, ZarrArray& chosen) {
    const std::uint64_t cap = memoryCap(options.maxMemoryBytes);
    const std::size_t count = image.levels.size();
    if (options.level) {
        if (*options.level < 0 || std::size_t(*options.level) >= count)
            throwInputError(image.store, "--level", "is " + std::to_string(*options.level) + "; the image has " +
                                                        std::to_string(count) + " levels (0 to " + std::to_string(count - 1) + ")");
        chosen = openLevel(image, std::size_t(*options.level), layout, cap);
        notes.push_back("level " + std::to_string(*options.level) + " of " + std::to_string(count) + " (--level)");
        return std::size_t(*options.level);
    }
    chosen = openLevel(image, 0, layout, cap);
    const double finestBytes = levelBytes(chosen, layout, options);
    if (finestBytes <= double(cap) || count == 1) {
        notes.push_back("level 0 of " + std::to_string(count) + ", the finest" + (count > 1 ? " (--level picks another)" : ""));
        return 0;
    }
    for (std::size_t level = 1; level < count; ++level) {
        ZarrArray coarser = openLevel(image, level, layout, cap);
        if (levelBytes(coarser, layout, options) <= double(cap)) {
            notes.push_back("level " + std::to_string(level) + " of " + std::to_string(count) + " (" +
                            dimsText(coarser, layout) + "): level 0 (" + dimsText(chosen, layout) + ") needs " +
                            byteCountText(finestBytes) + ", more than the " + byteCountText(double(cap)) + " allowed");
            chosen = std::move(coarser);
            return level;
        }
    }
    return 0;  // none fits: level 0, which the assembly's memory check then refuses with its remedies
}

std::size_t chooseChannel(const OmeMultiscales& image, const OmeLayout& layout, const ZarrArray& array,
                          const ReadOptions& options, std::vector<std::string>& notes) {
    const std::size_t count = layout.channel ? std::size_t(array.shape[*layout.channel]) : 1;
    const int asked = options.channel.value_or(0);
    if (asked < 0 || std::size_t(asked) >= count)
        throwInputError(image.store, "--channel", "is " + std::to_string(asked) + "; the image has " + std::to_string(count) +
                                                      (layout.channel ? " channels (0 to " + std::to_string(count - 1) + ")"
                                                                      : " channel (no channel axis)"));
    if (layout.channel) {
        const std::size_t channel = std::size_t(asked);
        const std::string label = channel < image.channelLabels.size() && !image.channelLabels[channel].empty()
                                      ? " (\"" + image.channelLabels[channel] + "\")"
                                      : "";
        notes.push_back("channel " + std::to_string(channel) + label + " of " + std::to_string(count) +
                        (options.channel ? " (--channel)" : " (--channel picks another)"));
    }
    return std::size_t(asked);
}

void requireChunksWorthReading(const ZarrArray& array, const OmeLayout& layout, const ReadOptions& options,
                               std::size_t stepCount) {
    double chunks = double(selectedSteps(options.steps, stepCount).size());
    for (std::size_t axis : layout.space) chunks *= std::ceil(double(array.shape[axis]) / double(array.chunkShape[axis]));
    const double values = double(selectedSteps(options.steps, stepCount).size()) * double(stepVoxels(array, layout));
    if (chunks > kTinyChunksRead && chunks * kFewestValuesPerChunk > values)
        throwInputError(array.metadataFile, array.zarrFormat == 2 ? "chunks" : "chunk_grid",
                        "reading the time-steps means looking for " + std::to_string(std::uint64_t(chunks)) +
                            " chunks of fewer than " + shortNumber(kFewestValuesPerChunk) +
                            " values each, too many file look-ups; rechunk the store");
}

std::filesystem::path storeOf(const std::filesystem::path& input) {
    std::error_code error;
    if (std::filesystem::is_directory(input, error)) return input;
    const std::filesystem::path parent = input.parent_path();
    return parent.empty() ? std::filesystem::path(".") : parent;
}

// The spacing, placement and meaning of x, y and z from the level's transforms.
struct OmeFrame {
    glm::dvec3 spacing{1.0};
    Placement placement;
    std::array<SpatialAxis, 3> axes;
};

OmeFrame frameOf(const OmeMultiscales& image, const OmeLayout& layout, std::size_t level) {
    const OmeLevel& transform = image.levels[level];
    OmeFrame frame;
    glm::dvec3 origin(0.0);
    static constexpr const char* kWorldNames[] = {"x", "y", "z"};
    for (std::size_t axis = 0; axis < 3; ++axis) {
        const std::size_t dimension = layout.space[axis];
        frame.spacing[int(axis)] = transform.scale[dimension];
        origin[int(axis)] = transform.translation[dimension];
        if (!(frame.spacing[int(axis)] > 0.0))
            throwInputError(image.attributesFile, "multiscales[0].datasets[" + std::to_string(level) + "].coordinateTransformations",
                            "the scale of axis \"" + image.axes[dimension].name + "\" is " +
                                shortNumber(frame.spacing[int(axis)]) + ": a spacing must be positive");
        frame.axes[axis] = {kWorldNames[axis], omeLengthUnit(image.axes[dimension].unit), AxisDirection::Unknown};
    }
    // Image viewers (napari, Fiji) draw row 0 at the top: turning the volume 180 degrees about x
    // makes y point down the screen and z away from the viewer without mirroring it.
    frame.placement.rotation = glm::angleAxis(std::numbers::pi, glm::dvec3(1.0, 0.0, 0.0));
    frame.placement.origin = frame.placement.rotation * origin;
    return frame;
}

// The time stamps: translation + index * scale of the t axis, in a unit TimeAxis knows.
std::vector<double> stepTimes(const OmeMultiscales& image, const OmeLayout& layout, std::size_t level, std::size_t stepCount,
                              SourceSeries& source) {
    if (!layout.time) return {0.0};
    const OmeLevel& transform = image.levels[level];
    const double scale = transform.scale[*layout.time];
    if (stepCount > 1 && !(scale > 0.0))
        throwInputError(image.attributesFile, "multiscales[0].datasets[" + std::to_string(level) + "].coordinateTransformations",
                        "the scale of the time axis is " + shortNumber(scale) + ": time-steps must follow one another");
    double factor = 1.0;
    source.time = omeTimeAxis(image.axes[*layout.time].unit, factor, source.notes);
    std::vector<double> times;
    for (std::size_t index = 0; index < stepCount; ++index)
        times.push_back((transform.translation[*layout.time] + double(index) * scale) * factor);
    return times;
}

std::string arrayNote(const OmeLevel& level, const ZarrArray& array) {
    std::string codecs;
    for (ZarrByteCodec codec : array.codecs) codecs += " " + toString(codec);
    return "array " + level.path + ": " + array.dataTypeText + (codecs.empty() ? ", uncompressed" : ", codecs" + codecs) +
           (array.sharding ? ", sharded" : "");
}

}  // namespace

bool isOmeZarrFolder(const std::filesystem::path& folder) {
    const std::filesystem::path group = zarrGroupFile(folder);
    if (group.empty()) return false;
    std::string name = folder.filename().string();
    if (name.empty()) name = folder.parent_path().filename().string();
    if (name.size() > 5 && name.compare(name.size() - 5, 5, ".zarr") == 0) return true;
    // The attributes name multiscales: a look for the word, the reader parses them.
    std::error_code error;
    for (const char* attributes : {"zarr.json", ".zattrs"}) {
        const std::filesystem::path file = folder / attributes;
        if (!std::filesystem::is_regular_file(file, error) || std::filesystem::file_size(file, error) > (16u << 20)) continue;
        std::ifstream in(file, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        if (text.str().find("\"multiscales\"") != std::string::npos) return true;
    }
    return false;
}

SourceSeries openOmeZarr(const std::filesystem::path& input, const ReadOptions& options) {
    const OmeMultiscales image = readOmeMultiscales(storeOf(input));
    const OmeLayout layout = layoutOf(image);
    SourceSeries source;
    const std::string version = image.version.empty() ? "" : " " + image.version;
    source.name = image.name.empty() ? storeOf(input).filename().string() : image.name;
    source.file = input;
    source.format = "OME-Zarr" + version;
    source.notes.push_back("OME-Zarr" + version + " on Zarr v" + std::to_string(image.zarrFormat) + ", axes " +
                           axisNames(image) + (image.name.empty() ? "" : ", image \"" + image.name + "\""));
    ZarrArray array;
    const std::size_t level = chooseLevel(image, layout, options, source.notes, array);
    const std::size_t channel = chooseChannel(image, layout, array, options, source.notes);
    source.notes.push_back(arrayNote(image.levels[level], array));
    const OmeFrame frame = frameOf(image, layout, level);
    source.axes = frame.axes;
    source.notes.push_back("turned 180 degrees about x: y runs down the screen (row 0 at the top, as image viewers show it)");

    const std::size_t stepCount = layout.time ? std::size_t(array.shape[*layout.time]) : 1;
    if (stepCount == 0) throwInputError(array.metadataFile, "shape", "the time axis holds no time-step");
    requireChunksWorthReading(array, layout, options, stepCount);
    RectilinearGrid grid;
    grid.dims = glm::ivec3(int(array.shape[layout.space[0]]), int(array.shape[layout.space[1]]),
                           int(array.shape[layout.space[2]]));
    grid.spacing = frame.spacing;
    for (double time : stepTimes(image, layout, level, stepCount, source)) {
        SourceStep step;
        step.time = time;
        step.grid = grid;
        step.placement = frame.placement;
        step.type = array.type;
        step.file = array.folder;
        source.steps.push_back(step);
    }
    auto shared = std::make_shared<const ZarrArray>(std::move(array));
    source.readStep = [shared, layout, channel, dims = grid.dims](std::size_t index) {
        ZarrVolumeSlice slice;
        slice.spaceDimensions = layout.space;
        slice.fixedIndex.assign(shared->shape.size(), 0);
        if (layout.time) slice.fixedIndex[*layout.time] = index;
        if (layout.channel) slice.fixedIndex[*layout.channel] = channel;
        std::vector<float> values = readZarrVolume(*shared, slice);
        refuseInfinities(values, dims, shared->metadataFile, index);
        return values;
    };
    return source;
}

}  // namespace tstyles
