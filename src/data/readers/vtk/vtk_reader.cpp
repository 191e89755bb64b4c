// From a ParaView series to time-steps: each file's own extent, frame and grid (moving data keeps
// its motion), one point array chosen for the whole series, values read one time-step at a time.
#include "vtk_reader.h"

#include <algorithm>
#include <iterator>
#include <memory>

#include "../infinite_values.h"
#include "../oriented_axes.h"
#include "vtk_legacy_file.h"
#include "vtk_xml_file.h"
#include "vtk_collection.h"
#include "vtk_series_file.h"
#include "tstyles/core/ascii_case.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/natural_order.h"

namespace tstyles {
namespace {

bool isListFile(const std::filesystem::path& file) {
    const std::string extension = lowercaseExtension(file);
    return extension == ".pvd" || extension == ".series";
}

// Whether the files are one numbered series (flow_0000.vtk, flow_0001.vtk, ...: one name pattern
// with its numbers apart).
bool isNumberedSeries(const std::vector<std::filesystem::path>& files) {
    if (files.size() < 2) return false;
    const std::string pattern = numberPattern(files.front().filename().string());
    if (pattern.find('#') == std::string::npos) return false;
    return std::all_of(files.begin(), files.end(), [&](const std::filesystem::path& file) {
        return numberPattern(file.filename().string()) == pattern;
    });
}

VtkCollection entriesOf(const std::vector<std::filesystem::path>& files) {
    if (files.size() == 1 && lowercaseExtension(files.front()) == ".pvd") return readPvdCollection(files.front());
    if (files.size() == 1 && lowercaseExtension(files.front()) == ".series") return readFileSeries(files.front());
    VtkCollection collection;
    for (const std::filesystem::path& file : files)
        if (isListFile(file))
            throwInputError(file, "", "a .pvd or .series file is a whole series: give it alone, not in a list");
    if (isNumberedSeries(files)) {
        const auto byNumber = [](const std::filesystem::path& a, const std::filesystem::path& b) {
            return naturalLess(a.filename().string(), b.filename().string());
        };
        // A shell's glob sorts flow_10 before flow_2: say so, but the order given is the user's.
        const auto unordered = std::is_sorted_until(files.begin(), files.end(), byNumber);
        if (unordered != files.end())
            collection.notes.push_back("the files are numbered (" + numberPattern(files.front().filename().string()) +
                                       ") but not given in number order: " + unordered->filename().string() +
                                       " comes after " + std::prev(unordered)->filename().string() +
                                       "; the time-steps follow the order given");
    }
    for (const std::filesystem::path& file : files)
        collection.entries.push_back({double(collection.entries.size()), file, ""});
    return collection;
}

struct ArrayChoice {
    std::string name;
    ValueType type = ValueType::Float32;
    std::vector<std::string> notes;
};

// --var, else the active Scalars, else the first single-component array.
ArrayChoice chooseArray(const VtkSeriesFile& file, const std::string& variable) {
    const auto& arrays = file.pointArrays();
    const VtkArraySummary* chosen = nullptr;
    std::string why;
    if (!variable.empty()) {
        chosen = &file.pointArray(variable);
        why = "asked for with --var";
    } else if (!file.activeScalars().empty()) {
        chosen = &file.pointArray(file.activeScalars());
        why = "the active Scalars array";
    } else {
        const auto single = std::find_if(arrays.begin(), arrays.end(),
                                         [](const VtkArraySummary& array) { return array.components == 1; });
        if (single == arrays.end()) {
            std::string problem = "no point array of one component to show; name one with --var (a vector is read "
                                  "as its magnitude)";
            std::string list;
            for (const VtkArraySummary& array : arrays) list += (list.empty() ? ": " : ", ") + arrayText(array);
            if (arrays.empty()) list = file.cellArrays().empty() ? ": the file has no arrays"
                                                                 : ": the file has only cell arrays, which are not read";
            throwInputError(file.path(), "PointData", problem + list);
        }
        chosen = &*single;
        why = "the first array of one component";
    }
    ArrayChoice choice{chosen->name, seriesValueType(chosen->type), {}};
    std::string others;
    for (const VtkArraySummary& array : arrays)
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
    if (!file.cellArrays().empty())
        choice.notes.push_back(std::to_string(file.cellArrays().size()) +
                               " cell array(s) not read: only point data is (values at the grid's points)");
    return choice;
}

struct StepSource {
    std::filesystem::path file;
    glm::ivec3 dims{0};
    bool mirrorX = false;
};

SourceStep describeStep(const VtkCollectionEntry& entry, const std::string& arrayName, ValueType type,
                        std::uint64_t memoryCap, StepSource& source) {
    SourceStep step;
    step.time = entry.time;
    step.type = type;
    step.file = entry.file;
    source.file = entry.file;
    const VtkSeriesFile file(entry.file, memoryCap);
    file.pointArray(arrayName);
    file.placeStep(step, source.mirrorX);
    source.dims = gridDims(step.grid);
    return step;
}

void describeSeries(SourceSeries& series, const std::vector<std::filesystem::path>& files,
                    const VtkCollection& collection, const VtkSeriesFile& first, const ArrayChoice& choice) {
    const std::string& kind = first.kindName();
    series.name = files.front().stem().string() + " (" + choice.name + ")";
    series.file = files.front();
    series.format = first.format();
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
    series.notes.push_back("data of " + first.path().filename().string() + ": " + first.encoding(choice.name));
    const std::vector<std::string> layout = first.layoutNotes();
    series.notes.insert(series.notes.end(), layout.begin(), layout.end());
}

}  // namespace

SourceSeries openVtkSeries(const std::vector<std::filesystem::path>& files, const ReadOptions& options) {
    const std::uint64_t cap = memoryCap(options.maxMemoryBytes);
    const VtkCollection collection = entriesOf(files);
    const VtkSeriesFile first(collection.entries.front().file, cap);
    const ArrayChoice choice = chooseArray(first, options.variable);

    SourceSeries series;
    describeSeries(series, files, collection, first, choice);
    auto sources = std::make_shared<std::vector<StepSource>>(collection.entries.size());
    for (std::size_t index = 0; index < collection.entries.size(); ++index)
        series.steps.push_back(describeStep(collection.entries[index], choice.name, choice.type, cap, (*sources)[index]));
    const std::string name = choice.name;
    series.readStep = [sources, name, cap](std::size_t index) {
        const StepSource& source = (*sources)[index];
        std::vector<float> values = readVtkSeriesValues(source.file, name, cap);
        refuseInfinities(values, source.dims, source.file, index);
        if (source.mirrorX) mirrorAlongX(values, source.dims);
        return values;
    };
    return series;
}

bool hasVtkSignature(const std::filesystem::path& file) { return looksLikeVtkXml(file) || looksLikeVtkLegacy(file); }

}  // namespace tstyles
