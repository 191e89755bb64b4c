// From a ParaView series to time-steps: each file's own extent, frame and grid (moving data keeps
// its motion), one point array chosen for the whole series, values read one time-step at a time.
#include "vtk_reader.h"

#include <algorithm>
#include <memory>

#include "infinite_values.h"
#include "oriented_axes.h"
#include "vtk_collection.h"
#include "vtk_dataset.h"
#include "tstyles/core/ascii_case.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/data/axis_nodes.h"

namespace tstyles {
namespace {

bool isListFile(const std::filesystem::path& file) {
    const std::string extension = lowercaseExtension(file);
    return extension == ".pvd" || extension == ".series";
}

VtkCollection entriesOf(const std::vector<std::filesystem::path>& files) {
    if (files.size() == 1 && lowercaseExtension(files.front()) == ".pvd") return readPvdCollection(files.front());
    if (files.size() == 1 && lowercaseExtension(files.front()) == ".series") return readFileSeries(files.front());
    VtkCollection collection;
    for (const std::filesystem::path& file : files) {
        if (isListFile(file))
            throwInputError(file, "", "a .pvd or .series file is a whole series: give it alone, not in a list");
        collection.entries.push_back({double(collection.entries.size()), file, ""});
    }
    return collection;
}

std::string arrayText(const VtkDataArray& array) {
    return array.name + (array.components > 1 ? " (" + std::to_string(array.components) + " components)" : "");
}

struct ArrayChoice {
    std::string name;
    ValueType type = ValueType::Float32;
    std::vector<std::string> notes;
};

// --var, else the active Scalars, else the first single-component array.
ArrayChoice chooseArray(const VtkXmlFile& file, const VtkDataset& dataset, const std::string& variable) {
    const auto& arrays = dataset.pieces.front().pointArrays;
    const VtkDataArray* chosen = nullptr;
    std::string why;
    if (!variable.empty()) {
        chosen = &pointArrayNamed(file, dataset, variable);
        why = "asked for with --var";
    } else if (!dataset.activeScalars.empty()) {
        chosen = &pointArrayNamed(file, dataset, dataset.activeScalars);
        why = "the active Scalars array";
    } else {
        const auto single = std::find_if(arrays.begin(), arrays.end(),
                                         [](const VtkDataArray& array) { return array.components == 1; });
        if (single == arrays.end()) {
            std::string problem = "no point array of one component to show; name one with --var (a vector is read "
                                  "as its magnitude)";
            std::string list;
            for (const VtkDataArray& array : arrays) list += (list.empty() ? ": " : ", ") + arrayText(array);
            if (arrays.empty()) list = dataset.cellArrays.empty() ? ": the file has no arrays"
                                                                  : ": the file has only cell arrays, which are not read";
            throwInputError(file.path, "PointData", problem + list);
        }
        chosen = &*single;
        why = "the first array of one component";
    }
    ArrayChoice choice{chosen->name, seriesValueType(chosen->type), {}};
    std::string others;
    for (const VtkDataArray& array : arrays)
        if (&array != chosen) others += (others.empty() ? "" : ", ") + arrayText(array);
    choice.notes.push_back("point array '" + chosen->name + "' (" + chosen->type.name + ", " + why + ")" +
                           (others.empty() ? "" : "; the others, for --var: " + others));
    if (chosen->components > 1) {
        choice.type = chosen->type.name == "Float64" ? ValueType::Float64 : ValueType::Float32;
        choice.notes.push_back("'" + chosen->name + "' has " + std::to_string(chosen->components) +
                               " components: its magnitude is shown");
    } else if (choice.type == ValueType::Float64 && chosen->type.name != "Float64") {
        choice.notes.push_back(chosen->type.name + " values are kept as Float64");
    }
    if (!dataset.cellArrays.empty())
        choice.notes.push_back(std::to_string(dataset.cellArrays.size()) +
                               " cell array(s) not read: only point data is (values at the grid's points)");
    return choice;
}

std::string encodingText(const VtkXmlFile& file, const VtkDataset& dataset, const std::string& name) {
    const VtkDataArray& array = pointArrayNamed(file, dataset, name);
    std::string text = array.format;
    if (array.format == "appended")
        text += file.appendedEncoding == VtkByteStream::Encoding::Raw ? " (raw)" : " (base64)";
    if (array.format != "ascii") {
        if (file.layout.compressor != VtkCompressor::None) text += ", compressed by " + toString(file.layout.compressor);
        text += file.layout.headerBytes == 8 ? ", UInt64 headers" : ", UInt32 headers";
        text += file.layout.bigEndian ? ", big-endian" : ", little-endian";
    }
    return text;
}

// The ImageData frame: VTK places point (i, j, k) at Origin + Direction * ((i, j, k) * Spacing),
// counting i, j, k from 0 even when the extent starts elsewhere.
OrientedAxes imageFrame(const VtkXmlFile& file, const VtkDataset& dataset) {
    const auto& d = dataset.direction;
    std::array<glm::dvec3, 3> axes{};
    for (int column = 0; column < 3; ++column)
        axes[std::size_t(column)] = glm::dvec3(d[std::size_t(column)], d[std::size_t(3 + column)],
                                               d[std::size_t(6 + column)]) *
                                    dataset.spacing[column];
    const glm::dvec3 first = dataset.origin + axes[0] * double(dataset.whole.bounds[0]) +
                             axes[1] * double(dataset.whole.bounds[2]) + axes[2] * double(dataset.whole.bounds[4]);
    return orientAxes(first, axes, dataset.whole.dims(), file.path, "Spacing and Direction");
}

// A rectilinear grid's coordinates as a grid with uneven axes where they are uneven: the first
// node at the placement's origin, the axes along x, y and z.
void placeRectilinear(const std::array<std::vector<double>, 3>& coordinates, const glm::ivec3& dims, SourceStep& step) {
    RectilinearGrid grid;
    grid.dims = dims;
    Placement placement;
    for (std::size_t axis = 0; axis < 3; ++axis) {
        // Even within what float32 coordinates can say: 1e-5 of the extent, (count - 1) mean gaps.
        AxisNodes nodes = axisNodesOf(coordinates[axis], 1e-5 * double(coordinates[axis].size() - 1));
        placement.origin[int(axis)] = nodes.origin;
        grid.spacing[int(axis)] = nodes.spacing;
        grid.axisPositions[axis] = std::move(nodes.positions);
    }
    step.grid = grid;
    step.placement = placement;
}

struct StepSource {
    std::filesystem::path file;
    bool mirrorX = false;
};

SourceStep describeStep(const VtkCollectionEntry& entry, const std::string& arrayName, ValueType type,
                        std::uint64_t memoryCap, StepSource& source) {
    SourceStep step;
    step.time = entry.time;
    step.type = type;
    step.file = entry.file;
    source.file = entry.file;
    const auto header = loadVtkXmlFile(entry.file, true, memoryCap);
    const VtkDataset dataset = describeVtkDataset(*header);
    pointArrayNamed(*header, dataset, arrayName);
    if (dataset.kind == VtkGridKind::Rectilinear) {
        const auto file = loadVtkXmlFile(entry.file, false, memoryCap);
        placeRectilinear(readVtkCoordinates(*file, dataset, memoryCap), dataset.whole.dims(), step);
        return step;
    }
    if (dataset.kind == VtkGridKind::Structured) {
        const auto file = loadVtkXmlFile(entry.file, false, memoryCap);
        StructuredGrid grid = makeStructuredGrid(dataset.whole.dims(), readVtkPoints(*file, dataset, memoryCap), entry.file);
        if (const auto problem = findGridProblem(grid)) throwInputError(entry.file, "Points", *problem);
        step.grid = std::move(grid);
        return step;
    }
    const OrientedAxes frame = imageFrame(*header, dataset);
    RectilinearGrid grid;
    grid.dims = dataset.whole.dims();
    grid.spacing = frame.spacing;
    step.grid = grid;
    step.placement = frame.placement;
    source.mirrorX = frame.mirrorX;
    return step;
}

void describeSeries(SourceSeries& series, const std::vector<std::filesystem::path>& files,
                    const VtkCollection& collection, const VtkXmlFile& first, const VtkDataset& dataset,
                    const ArrayChoice& choice) {
    const std::string kind = toString(dataset.kind);
    series.name = files.front().stem().string() + " (" + choice.name + ")";
    series.file = files.front();
    series.format = "VTK XML " + kind;
    for (int axis = 0; axis < 3; ++axis)
        series.axes[std::size_t(axis)] = {std::string(1, char('x' + axis)), "", AxisDirection::Unknown};
    series.time.unit = TimeUnit::None;
    const std::size_t count = collection.entries.size();
    const bool listed = files.size() == 1 && isListFile(files.front());
    series.notes.push_back(std::to_string(count) + " " + kind + " file(s)" +
                           (listed ? " listed in " + files.front().filename().string() +
                                         ", times as it gives them (no unit)"
                                   : count > 1 ? ", one time-step each, times 0, 1, 2, ... in the order given" : ""));
    series.notes.insert(series.notes.end(), collection.notes.begin(), collection.notes.end());
    series.notes.insert(series.notes.end(), choice.notes.begin(), choice.notes.end());
    series.notes.push_back("data of " + first.path.filename().string() + ": " +
                           encodingText(first, dataset, choice.name));
    if (dataset.pieces.size() > 1)
        series.notes.push_back(first.path.filename().string() + " holds " + std::to_string(dataset.pieces.size()) +
                               " pieces, assembled into its WholeExtent");
}

}  // namespace

SourceSeries openVtkSeries(const std::vector<std::filesystem::path>& files, const ReadOptions& options) {
    const std::uint64_t cap = memoryCap(options.maxMemoryBytes);
    const VtkCollection collection = entriesOf(files);
    const auto first = loadVtkXmlFile(collection.entries.front().file, true, cap);
    const VtkDataset firstDataset = describeVtkDataset(*first);
    const ArrayChoice choice = chooseArray(*first, firstDataset, options.variable);

    SourceSeries series;
    describeSeries(series, files, collection, *first, firstDataset, choice);
    auto sources = std::make_shared<std::vector<StepSource>>(collection.entries.size());
    for (std::size_t index = 0; index < collection.entries.size(); ++index)
        series.steps.push_back(describeStep(collection.entries[index], choice.name, choice.type, cap, (*sources)[index]));
    const std::string name = choice.name;
    series.readStep = [sources, name, cap](std::size_t index) {
        const StepSource& source = (*sources)[index];
        const auto file = loadVtkXmlFile(source.file, false, cap);
        const VtkDataset dataset = describeVtkDataset(*file);
        std::vector<float> values = readVtkPointArray(*file, dataset, name, cap);
        refuseInfinities(values, dataset.whole.dims(), source.file, index);
        if (source.mirrorX) mirrorAlongX(values, dataset.whole.dims());
        return values;
    };
    return series;
}

bool hasVtkXmlSignature(const std::filesystem::path& file) { return looksLikeVtkXml(file); }

}  // namespace tstyles
