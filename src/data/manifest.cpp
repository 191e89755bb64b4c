// Loading a series: parse and check the JSON manifest, then read every value and mask file it names
// and map the raw values to density by the series' value range.
#include "tstyles/data/manifest.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <cmath>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "beam_grid_field.h"
#include "grid_dims_field.h"
#include "tstyles/core/json_text.h"
#include "raw_values.h"
#include "structured_grid_files.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/user_paths.h"

namespace tstyles {
namespace {

constexpr const char* kManifestFormat = "tstyles-series";
constexpr int kManifestVersion = 1;
constexpr const char* kManifestFileName = "series.json";
// Far beyond any volume a GPU holds, and small enough that byte counts cannot overflow.

// A time-step as the manifest describes it, before its files are read.
struct StepEntry {
    TimeStep step;
    std::string valuesField;
    std::string maskField;  // empty when the time-step has no mask
};

std::string numberText(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

// A dataset may be named by its folder; the manifest inside is then series.json.
std::filesystem::path manifestFileOf(const std::filesystem::path& dataset) {
    std::error_code error;
    if (std::filesystem::is_directory(dataset, error)) return dataset / kManifestFileName;
    return dataset;
}

// A scene (it names a dataset, may hold comments) given where a dataset belongs: said as such
// rather than as the manifest keys it lacks.
bool looksLikeScene(const std::string& text) {
    const nlohmann::json document = probeJsonText(text, JsonComments::Allowed);
    return document.is_object() && document.contains("dataset") && !document.contains("format");
}

nlohmann::json parseManifest(const std::filesystem::path& file) {
    if (userPathKind({}, file) == PathKind::Missing) throwInputError(file, "", "manifest not found");
    requireRegularFile(file, "manifest");
    std::ifstream in(file, std::ios::binary);
    if (!in) throwInputError(file, "", "cannot open the manifest for reading");
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throwInputError(file, "", "cannot read the manifest");
    if (looksLikeScene(text))
        throwInputError(file, "",
                        "is a scene file, not a dataset: render it with `tstyles render " + file.string() +
                            " -o OUT.png`, or give `info` the dataset it names");
    return parseJsonText(text, file, JsonComments::Refused);
}

std::filesystem::path resolveBeside(const std::filesystem::path& manifest, const JsonField& name) {
    const std::string text = name.string();
    if (text.empty()) name.fail("must name a file");
    requireUsablePathName({name.file(), name.path()}, text);
    const std::filesystem::path file = text;
    return file.is_absolute() ? file : manifest.parent_path() / file;
}

// An uneven axis: dims[axis] finite grid-local node positions, the first 0, strictly increasing.
std::vector<double> readAxisPositions(const JsonField& field, int count) {
    if (field.arraySize() != std::size_t(count)) {
        field.fail("expected " + std::to_string(count) + " node positions (one per sample along the axis), found " +
                   std::to_string(field.arraySize()));
    }
    std::vector<double> positions;
    for (std::size_t node = 0; node < std::size_t(count); ++node) {
        const JsonField element = field.element(node);
        positions.push_back(element.finiteNumber());
        if (node == 0 && positions[0] != 0.0)
            element.fail("the first node must be at 0 (the placement origin), found " + numberText(positions[0]));
        if (node > 0 && !(positions[node] > positions[node - 1])) {
            element.fail("node positions must be strictly increasing: " + numberText(positions[node]) + " follows " +
                         numberText(positions[node - 1]));
        }
    }
    return positions;
}

RectilinearGrid readRectilinearGrid(const JsonField& field) {
    field.allowOnlyKeys({"type", "dims", "spacing", "positions"});
    RectilinearGrid grid;
    const JsonField dims = field.member("dims");
    const JsonField spacing = field.member("spacing");
    const auto positions = field.optionalMember("positions");
    if (positions) positions->allowOnlyKeys({"x", "y", "z"});
    grid.dims = readGridDims(dims, kMaxVoxelsPerStep,
                             {"expected 3 sample counts (x, y, z)",
                              "a grid needs two samples along each axis to span a box",
                              "too many voxels for one time-step"});
    if (spacing.arraySize() != 3) spacing.fail("expected 3 distances (x, y, z)");
    for (int axis = 0; axis < 3; ++axis) {
        const JsonField distance = spacing.element(std::size_t(axis));
        const std::string axisName(1, "xyz"[axis]);
        const auto axisPositions = positions ? positions->optionalMember(axisName) : std::nullopt;
        // An uneven axis has its nodes in "positions" and null in "spacing", so that no number in the
        // manifest goes unused.
        if (axisPositions) {
            if (!distance.isNull())
                distance.fail("must be null: the nodes of axis " + axisName + " are given by grid.positions." + axisName);
            grid.axisPositions[std::size_t(axis)] = readAxisPositions(*axisPositions, grid.dims[axis]);
            grid.spacing[axis] = grid.axisPositions[std::size_t(axis)].back() / double(grid.dims[axis] - 1);
            continue;
        }
        if (distance.isNull()) distance.fail("null needs the axis' node positions in grid.positions." + axisName);
        grid.spacing[axis] = distance.finiteNumber();
        if (grid.spacing[axis] <= 0.0)
            distance.fail("must be positive, found " + numberText(grid.spacing[axis]));
    }
    return grid;
}

Grid readGrid(const JsonField& field, std::size_t stepIndex, StructuredGridFiles& structuredGrids) {
    const JsonField type = field.member("type");
    if (type.string() == "rectilinear") return readRectilinearGrid(field);
    if (type.string() == "structured") return structuredGrids.read(field, stepIndex);
    if (type.string() == "beam") return readBeamGrid(field);
    type.fail("unknown grid type '" + type.string() + "' (known: rectilinear, structured, beam)");
}

Placement readPlacement(const std::optional<JsonField>& field) {
    Placement placement;
    if (!field) return placement;
    field->allowOnlyKeys({"origin", "rotation"});
    if (const auto origin = field->optionalMember("origin")) placement.origin = origin->vec3();
    if (const auto rotation = field->optionalMember("rotation")) {
        rotation->allowOnlyKeys({"axis", "angle_deg"});
        const JsonField axisField = rotation->member("axis");
        AxisAngle axisAngle;
        axisAngle.axis = axisField.vec3();
        if (!(glm::length(axisAngle.axis) > 0.0)) axisField.fail("rotation axis must not be zero");
        axisAngle.angleDeg = rotation->member("angle_deg").finiteNumber();
        placement.rotation = fromAxisAngle(axisAngle);
    }
    return placement;
}

StepEntry readStepEntry(const JsonField& field, std::size_t stepIndex, StructuredGridFiles& structuredGrids) {
    field.allowOnlyKeys({"time", "grid", "placement", "values", "mask"});
    StepEntry entry;
    entry.step.time = field.member("time").finiteNumber();
    entry.step.grid = readGrid(field.member("grid"), stepIndex, structuredGrids);
    entry.step.placement = readPlacement(field.optionalMember("placement"));

    const JsonField values = field.member("values");
    values.allowOnlyKeys({"file", "type"});
    const JsonField valuesFile = values.member("file");
    entry.step.valuesFile = resolveBeside(field.file(), valuesFile);
    entry.valuesField = valuesFile.path();
    const JsonField type = values.member("type");
    const auto valueType = valueTypeFromString(type.string());
    if (!valueType) type.fail("unknown value type '" + type.string() + "' (known: uint8, uint16, float32, int8, int16, int32, float64)");
    entry.step.sourceType = *valueType;

    if (const auto mask = field.optionalMember("mask")) {
        mask->allowOnlyKeys({"file"});
        const JsonField maskFile = mask->member("file");
        entry.step.maskFile = resolveBeside(field.file(), maskFile);
        entry.maskField = maskFile.path();
    }
    return entry;
}

std::vector<StepEntry> readStepEntries(const JsonField& field) {
    const std::size_t count = field.arraySize();
    if (count == 0) field.fail("must list at least one time-step");
    std::vector<StepEntry> entries;
    entries.reserve(count);
    StructuredGridFiles structuredGrids;
    for (std::size_t index = 0; index < count; ++index) {
        const JsonField stepField = field.element(index);
        entries.push_back(readStepEntry(stepField, index, structuredGrids));
        // Time orders the series everywhere (TSTF axes, playback), so ties are as wrong as reversals.
        if (index > 0 && !(entries[index].step.time > entries[index - 1].step.time)) {
            stepField.member("time").fail(
                "times must be strictly increasing: " + numberText(entries[index].step.time) + " follows " +
                numberText(entries[index - 1].step.time));
        }
    }
    return entries;
}

std::optional<std::array<double, 2>> readValueRange(const std::optional<JsonField>& field) {
    if (!field) return std::nullopt;
    if (field->arraySize() != 2) field->fail("expected [low, high]");
    const std::array<double, 2> range{field->element(0).finiteNumber(), field->element(1).finiteNumber()};
    if (!(range[0] < range[1])) {
        field->fail("low must be less than high, found [" + numberText(range[0]) + ", " +
                    numberText(range[1]) + "]");
    }
    return range;
}

// The raw value that marks a voxel without data: a number, or the string "NaN" (JSON has no NaN).
std::optional<double> readMissingValue(const std::optional<JsonField>& field) {
    if (!field) return std::nullopt;
    if (field->isString()) {
        if (field->string() != "NaN") field->fail("expected a number or \"NaN\", found \"" + field->string() + "\"");
        return std::numeric_limits<double>::quiet_NaN();
    }
    return field->finiteNumber();
}

void readStepFiles(const std::filesystem::path& manifest, std::size_t index, StepEntry& entry,
                   std::optional<double> missingMarker, const std::optional<NodeBlock>& kept, BlockReach reach) {
    TimeStep& step = entry.step;
    // The raw files hold one value per node whatever the grid kind: only the dims matter here.
    RawValues raw = readRawValues({manifest, entry.valuesField, index, step.valuesFile}, step.dims(),
                                  step.sourceType, missingMarker, kept, reach);
    step.density = std::move(raw.values);  // still raw: normalised once the value range is known
    step.rawRange = raw.range;
    if (!entry.maskField.empty()) {
        step.mask = readMask({manifest, entry.maskField, index, step.maskFile}, step.dims(), kept);
    }
}

std::array<double, 2> valueRangeFromData(const std::filesystem::path& manifest,
                                         const std::vector<StepEntry>& entries) {
    // Time-steps whose every value is missing have a NaN range and add nothing.
    std::array<double, 2> range{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const StepEntry& entry : entries) {
        if (std::isnan(entry.step.rawRange[0])) continue;
        range[0] = std::min(range[0], entry.step.rawRange[0]);
        range[1] = std::max(range[1], entry.step.rawRange[1]);
    }
    if (range[0] > range[1]) {
        throwInputError(manifest, "value_range",
                        "not given, and every value of every time-step is missing, so no range can be derived: "
                        "give \"value_range\": [low, high]");
    }
    if (range[0] == range[1]) {
        throwInputError(manifest, "value_range",
                        "not given, and every value of every time-step is " + numberText(range[0]) +
                            ", so no range can be derived: give \"value_range\": [low, high]");
    }
    return range;
}

// "time_units" (CF, "days since 1950-01-01"), "calendar" and "climatology" (true: the stamps stand
// for the same period of every year), all optional.
TimeAxis readTimeAxis(const std::filesystem::path& manifest, const JsonField& root) {
    const auto units = root.optionalMember("time_units");
    const auto calendar = root.optionalMember("calendar");
    TimeAxis axis = parseTimeUnits(units ? units->string() : "", calendar ? calendar->string() : "", manifest, "time");
    if (const auto climatology = root.optionalMember("climatology")) axis.climatology = climatology->boolean();
    return axis;
}

// "axes": three objects {"name", "unit", "direction", "negated"}, each key optional.
std::array<SpatialAxis, 3> readAxes(const JsonField& field) {
    if (field.arraySize() != 3) field.fail("expected three axes (x, y, z), got " + std::to_string(field.arraySize()));
    std::array<SpatialAxis, 3> axes;
    for (std::size_t index = 0; index < 3; ++index) {
        const JsonField axis = field.element(index);
        axis.allowOnlyKeys({"name", "unit", "direction", "negated"});
        if (const auto negated = axis.optionalMember("negated")) axes[index].negated = negated->boolean();
        if (const auto name = axis.optionalMember("name")) axes[index].name = name->string();
        if (const auto unit = axis.optionalMember("unit")) axes[index].unit = unit->string();
        if (const auto direction = axis.optionalMember("direction")) {
            const auto parsed = axisDirectionFromString(direction->string());
            if (!parsed)
                direction->fail("unknown direction \"" + direction->string() +
                                "\"; allowed: east, west, north, south, up, down, right, left, anterior, posterior, "
                                "superior, inferior, unknown");
            axes[index].direction = *parsed;
        }
    }
    return axes;
}

// Before any value file is read: the whole series under the memory limit, or where only a block
// of each time-step is kept, the voxels kept.
void requireSeriesMemory(const std::filesystem::path& manifest, const std::vector<StepEntry>& entries,
                         const ManifestLimits& limits) {
    const bool masks = std::any_of(entries.begin(), entries.end(), [](const StepEntry& e) { return !e.maskField.empty(); });
    double whole = 0.0;
    for (const StepEntry& entry : entries) {
        const glm::ivec3 dims = entry.step.dims();
        const double voxels = double(dims.x) * double(dims.y) * double(dims.z);
        whole += voxels * double(sizeof(float) + limits.gpuBytesPerVoxel + (entry.maskField.empty() ? 0 : 1));
    }
    const std::string perVoxel = " (4 bytes a voxel in memory, " + std::to_string(limits.gpuBytesPerVoxel) +
                                 " on the GPU, 1 per mask)";
    if (!limits.nodesToRead) {
        requireMemory(manifest, "time_steps", whole, memoryCap(limits.maxMemoryBytes),
                      "the series' " + std::to_string(entries.size()) + " time-step(s)" + perVoxel);
        return;
    }
    const double bytesPerVoxel = double(sizeof(float) + limits.gpuBytesPerVoxel + (masks ? 1 : 0));
    requireMemory(manifest, "time_steps", double(limits.keptVoxels) * bytesPerVoxel, memoryCap(limits.maxMemoryBytes),
                  "the " + std::to_string(limits.keptVoxels) + " voxels kept of its time-steps" + perVoxel);
}

std::string defaultName(const std::filesystem::path& manifest) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(manifest, error);
    return (error ? manifest : absolute).parent_path().filename().string();
}

}  // namespace

namespace {

// The manifest read and checked, no value or mask file opened yet.
struct ParsedManifest {
    Series series;  // everything but the time-steps and the value range
    std::vector<StepEntry> entries;
    std::optional<std::array<double, 2>> explicitRange;
    std::optional<double> missingMarker;
};

ParsedManifest parseSeriesManifest(const std::filesystem::path& manifestPath) {
    const std::filesystem::path manifest = manifestFileOf(manifestPath);
    const nlohmann::json document = parseManifest(manifest);
    const JsonField root(manifest, document, "");

    // Format and version first: a different kind of JSON file should not be reported key by key.
    const JsonField format = root.member("format");
    if (format.string() != kManifestFormat) {
        format.fail("expected \"" + std::string(kManifestFormat) + "\", found \"" + format.string() + "\"");
    }
    const JsonField version = root.member("version");
    if (version.integer() != kManifestVersion) {
        version.fail("unsupported version " + std::to_string(version.integer()) + " (this build reads " +
                     std::to_string(kManifestVersion) + ")");
    }
    root.allowOnlyKeys(
        {"format", "version", "name", "value_range", "missing_value", "time_units", "calendar", "climatology", "axes",
         "time_steps"});

    ParsedManifest parsed;
    Series& series = parsed.series;
    series.manifestPath = manifest;
    const auto name = root.optionalMember("name");
    series.name = name ? name->string() : defaultName(manifest);
    parsed.explicitRange = readValueRange(root.optionalMember("value_range"));
    parsed.missingMarker = readMissingValue(root.optionalMember("missing_value"));
    parsed.entries = readStepEntries(root.member("time_steps"));
    series.time = readTimeAxis(manifest, root);
    if (const auto axes = root.optionalMember("axes")) series.axes = readAxes(*axes);
    return parsed;
}

}  // namespace

Series loadSeries(const std::filesystem::path& manifestPath, const ManifestLimits& limits) {
    ParsedManifest parsed = parseSeriesManifest(manifestPath);
    Series series = std::move(parsed.series);
    std::vector<StepEntry>& entries = parsed.entries;
    const std::filesystem::path& manifest = series.manifestPath;

    requireSeriesMemory(manifest, entries, limits);
    // A block needs the whole files read through only where they decide the value range.
    const BlockReach reach = parsed.explicitRange ? BlockReach::BlockRows : BlockReach::WholeFile;
    for (std::size_t index = 0; index < entries.size(); ++index) {
        const std::optional<NodeBlock> kept =
            limits.nodesToRead ? limits.nodesToRead(index, entries[index].step) : std::nullopt;
        readStepFiles(manifest, index, entries[index], parsed.missingMarker, kept, reach);
        if (limits.afterStepRead) limits.afterStepRead(index, entries[index].step);
    }
    series.valueRange = parsed.explicitRange ? *parsed.explicitRange : valueRangeFromData(manifest, entries);

    series.steps.reserve(entries.size());
    for (StepEntry& entry : entries) {
        normalizeToDensity(entry.step.density, series.valueRange);
        series.steps.push_back(std::move(entry.step));
    }
    return series;
}

Series loadSeriesOutline(const std::filesystem::path& manifestPath) {
    ParsedManifest parsed = parseSeriesManifest(manifestPath);
    Series series = std::move(parsed.series);
    const double unknown = std::numeric_limits<double>::quiet_NaN();
    series.valueRange = parsed.explicitRange.value_or(std::array<double, 2>{unknown, unknown});
    for (StepEntry& entry : parsed.entries) series.steps.push_back(std::move(entry.step));
    return series;
}

}  // namespace tstyles
