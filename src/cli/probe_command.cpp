// `tstyles probe DATASET --at X,Y,Z | --voxel I,J,K | --along X,Y,Z:X,Y,Z`: the values of a place
// over time, or of a line (a Hovmoeller table: time x distance), as text, CSV or JSON
// (docs/probe.md).
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "image_size_text.h"
#include "tstyles/annotate/probe_plot.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/interval.h"
#include "tstyles/data/format_listing.h"
#include "tstyles/data/probe_csv.h"
#include "tstyles/data/temporal_probe.h"
#include "tstyles/data/time_axis.h"
#include "tstyles/image/image_io.h"
#include "tstyles/scene/time_colours.h"

namespace tstyles::cli {
namespace {

struct ProbeOptions {
    std::string at;
    std::string voxel;
    std::string along;
    std::size_t points = 50;
    bool json = false;
    bool csv = false;
    std::filesystem::path plot;  // -o: the picture of the table
    std::string plotSize = "800x450";
};

// "X,Y,Z" as three finite numbers, or an InputError naming the option.
glm::dvec3 parseTriple(const std::string& text, const std::string& option, const std::string& what) {
    std::vector<double> numbers;
    std::stringstream stream(text);
    for (std::string part; std::getline(stream, part, ',');) {
        std::size_t used = 0;
        double value = 0.0;
        try {
            value = std::stod(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || part.find_first_not_of(" \t", used) != std::string::npos || !std::isfinite(value))
            throwInputError("", option, "expected " + what + " as three numbers separated by commas, got \"" + text + "\"");
        numbers.push_back(value);
    }
    if (numbers.size() != 3 || text.empty() || text.back() == ',')
        throwInputError("", option,
                        "expected " + what + " as three numbers separated by commas, got \"" + text + "\" (" +
                            std::to_string(numbers.size()) + " number" + (numbers.size() == 1 ? "" : "s") + ")");
    return {numbers[0], numbers[1], numbers[2]};
}

glm::ivec3 parseNode(const std::string& text) {
    const glm::dvec3 numbers = parseTriple(text, "--voxel", "node indices I,J,K");
    for (int axis = 0; axis < 3; ++axis)
        if (numbers[axis] != std::floor(numbers[axis]) || std::abs(numbers[axis]) > 1e9)
            throwInputError("", "--voxel", "node indices are whole numbers, got \"" + text + "\"");
    return glm::ivec3(numbers);
}

std::string pointText(const glm::dvec3& point) {
    return "(" + formatNumber(point.x) + ", " + formatNumber(point.y) + ", " + formatNumber(point.z) + ")";
}

// The places probed: one (--at, --voxel) or a line of them (--along), checked to meet a grid.
struct ProbePlaces {
    std::vector<glm::dvec3> points;  // in the world, where the time-steps are sampled
    std::vector<glm::dvec3> shown;   // the same in the file's coordinates (fileCoordinatesOf), as given
    std::vector<double> distances;  // along the line from its start; {0} for one place
    bool line = false;
    std::string option;  // the option that gave them, for messages
};

ProbePlaces placesOf(const ProbeOptions& options, const Series& series) {
    const int given = int(!options.at.empty()) + int(!options.voxel.empty()) + int(!options.along.empty());
    if (given != 1) throwInputError("", "--at", "give exactly one of --at X,Y,Z, --voxel I,J,K and --along A:B");
    ProbePlaces places;
    if (!options.at.empty()) {
        places.points = {worldCoordinatesOf(series, parseTriple(options.at, "--at", "a place X,Y,Z"))};
        places.option = "--at";
    }
    if (!options.voxel.empty()) {
        places.points = {nodePosition(series.steps.front(), parseNode(options.voxel), "--voxel")};
        places.option = "--voxel";
    }
    if (!options.along.empty()) {
        const std::size_t colon = options.along.find(':');
        if (colon == std::string::npos)
            throwInputError("", "--along", "expected two places X,Y,Z:X,Y,Z, got \"" + options.along + "\"");
        const glm::dvec3 from =
            worldCoordinatesOf(series, parseTriple(options.along.substr(0, colon), "--along", "the line's start"));
        const glm::dvec3 to =
            worldCoordinatesOf(series, parseTriple(options.along.substr(colon + 1), "--along", "the line's end"));
        if (glm::length(to - from) <= 0.0)
            throwInputError("", "--along",
                            "the line " + pointText(fileCoordinatesOf(series, from)) + " to " +
                                pointText(fileCoordinatesOf(series, to)) + " has zero length");
        if (options.points < 2) throwInputError("", "--points", "a line needs at least 2 points, got " + std::to_string(options.points));
        places.points = pointsAlong(from, to, options.points);
        places.line = true;
        places.option = "--along";
    }
    for (const glm::dvec3& point : places.points) {
        places.distances.push_back(glm::length(point - places.points.front()));
        places.shown.push_back(fileCoordinatesOf(series, point));
    }
    return places;
}

bool inside(const Bounds& bounds, const glm::dvec3& point) {
    return glm::all(glm::greaterThanEqual(point, bounds.lower)) && glm::all(glm::lessThanEqual(point, bounds.upper));
}

// A place outside every grid is a mistake (a coordinate in the wrong unit, a swapped axis): say so
// with the bounds. Inside a grid where there is no data (land, a mask) is an answer: missing.
void requireSomeGridMet(const Series& series, const ProbePlaces& places,
                        const std::vector<std::vector<std::optional<double>>>& values) {
    for (const auto& column : values)
        for (const auto& value : column)
            if (value) return;
    for (const glm::dvec3& point : places.points)
        for (std::size_t step = 0; step < series.steps.size(); ++step)
            if (inside(series.worldBounds(step), point)) return;
    const Bounds bounds = fileBounds(series);
    const std::string what = places.line ? "the line from " + pointText(places.shown.front()) + " to " +
                                               pointText(places.shown.back())
                                         : "the place " + pointText(places.shown.front());
    throwInputError("", places.option,
                    what + " is outside every time-step's grid; the series spans " + pointText(bounds.lower) +
                        " to " + pointText(bounds.upper) +
                        (hasNegatedAxes(series) ? " (in the file's coordinates, as `tstyles info` lists them)"
                                                : " (its world bounds, as `tstyles info` lists them)"));
}

double asStored(double value) { return std::stod(storedValueText(value)); }

void writeJson(const Series& series, const ProbePlaces& places, const std::vector<std::string>& labels,
               const std::vector<std::vector<std::optional<double>>>& values) {
    nlohmann::ordered_json json;
    json["series"] = series.name;
    json["unit"] = series.valueUnit;
    json["times"] = nlohmann::json::array();
    for (const TimeStep& step : series.steps) json["times"].push_back(step.time);
    if (series.time.unit != TimeUnit::None) {
        json["time_units"] = toCfUnits(series.time);
        if (series.time.reference) json["calendar"] = toString(series.time.calendar);
    }
    json["time_labels"] = labels;
    const auto valueOf = [](const std::optional<double>& value) {
        return value ? nlohmann::ordered_json(asStored(*value)) : nlohmann::ordered_json(nullptr);
    };
    if (!places.line) {
        json["at"] = {places.shown.front().x, places.shown.front().y, places.shown.front().z};
        json["values"] = nlohmann::json::array();
        for (const auto& value : values.front()) json["values"].push_back(valueOf(value));
    } else {
        json["points"] = nlohmann::json::array();
        for (const glm::dvec3& point : places.shown) json["points"].push_back({point.x, point.y, point.z});
        json["distances"] = places.distances;
        json["values"] = nlohmann::json::array();  // one row per time-step, one value per point
        for (std::size_t step = 0; step < series.steps.size(); ++step) {
            auto row = nlohmann::ordered_json::array();
            for (const auto& column : values) row.push_back(valueOf(column[step]));
            json["values"].push_back(row);
        }
    }
    std::cout << json.dump(2) << "\n";
}

void writeCsv(const Series& series, const ProbePlaces& places, const std::vector<std::string>& labels,
              const std::vector<std::vector<std::optional<double>>>& values) {
    ProbeColumns columns{{}, labels, {}, values};
    for (const TimeStep& step : series.steps) columns.times.push_back(step.time);
    if (!places.line) columns.headers = {"value"};
    else
        for (double distance : places.distances) columns.headers.push_back(storedValueText(distance));
    writeProbeCsv(std::cout, columns);
}

void writeText(const Series& series, const ProbePlaces& places, const std::vector<std::string>& labels,
               const std::vector<std::vector<std::optional<double>>>& values) {
    const std::string unit = series.valueUnit.empty() ? "no unit" : series.valueUnit;
    if (!places.line) {
        std::cout << series.name << " at " << pointText(places.shown.front()) << " (" << unit << "):\n"
                  << "  #  time  value\n";
        for (std::size_t step = 0; step < series.steps.size(); ++step) {
            const auto& value = values.front()[step];
            std::cout << "  " << step << "  " << labels[step] << "  "
                      << (value ? storedValueText(*value) : "missing (outside this time-step's grid or no data)") << "\n";
        }
        return;
    }
    std::cout << series.name << " along " << pointText(places.shown.front()) << " to "
              << pointText(places.shown.back()) << ", " << places.points.size() << " points (" << unit
              << "); rows: time-steps, columns: distance from the start\n";
    std::cout << "time";
    for (double distance : places.distances) std::cout << "\t" << storedValueText(distance);
    std::cout << "\n";
    for (std::size_t step = 0; step < series.steps.size(); ++step) {
        std::cout << labels[step];
        for (const auto& column : values) std::cout << "\t" << (column[step] ? storedValueText(*column[step]) : "-");
        std::cout << "\n";
    }
}

ProbeTable tableOf(const Series& series, const ProbePlaces& places, const std::vector<std::string>& labels,
                   const std::vector<std::vector<std::optional<double>>>& values) {
    ProbeTable table;
    table.title = series.name + (places.line ? " along " + pointText(places.shown.front()) + " to " +
                                                   pointText(places.shown.back())
                                             : " at " + pointText(places.shown.front()));
    table.unit = series.valueUnit;
    for (const TimeStep& step : series.steps) table.times.push_back(step.time);
    table.timeLabels = labels;
    table.distances = places.distances;
    table.values = values;
    return table;
}

// Each time-step's colour as `render` of the dataset shows time: the automatic scene's index TSTF.
std::vector<glm::vec3> automaticTimeColours(const Series& series) {
    Scene scene;
    applyTimeColours(scene, series.size());
    std::vector<glm::vec3> colours;
    for (std::size_t step = 0; step < series.size(); ++step)
        colours.push_back(glm::vec3(scene.indexTstf.atStep(int(step)).color));
    return colours;
}

}  // namespace

Command addProbeCommand(CLI::App& app) {
    auto inputs = std::make_shared<std::vector<std::filesystem::path>>();
    auto dataset = std::make_shared<DatasetOptions>();
    auto options = std::make_shared<ProbeOptions>();
    CLI::App* command = app.add_subcommand(
        "probe", "The values of a place over time (--at, --voxel), or of a line (--along): a table of time and value");
    command->add_option("dataset", *inputs, std::string("Dataset: ") + datasetKindsText())->required();
    command->add_option("--at", options->at,
                        "The place X,Y,Z in the file's coordinates, as `tstyles info` lists its bounds (a depth or "
                        "pressure level as the file counts it: 500 for 500 hPa)");
    command->add_option("--voxel", options->voxel, "The node I,J,K of the first time-step's grid, each from 0");
    command->add_option("--along", options->along,
                        "A line X,Y,Z:X,Y,Z: the values of --points places along it per time-step (a Hovmoeller table)");
    command->add_option("--points", options->points, "Places along --along, both ends included (default 50)");
    command->add_flag("--json", options->json, "Write JSON: times, their labels, the values (null where missing)");
    command->add_flag("--csv", options->csv, "Write CSV: one row per time-step");
    command->add_option("-o,--output", options->plot,
                        "Also draw the table: a line plot of one place, a Hovmoeller diagram of a line (PNG, ...)");
    command->add_option("--size", options->plotSize, "The picture's size WIDTHxHEIGHT (default 800x450)");
    addDatasetOptions(*command, *dataset);
    return {command, [inputs, dataset, options] {
                if (options->json && options->csv) throwInputError("", "--csv", "give --json or --csv, not both");
                // Checked before the series is read: a typing mistake should not wait for the data.
                if (!options->at.empty()) parseTriple(options->at, "--at", "a place X,Y,Z");
                if (!options->voxel.empty()) parseNode(options->voxel);
                const glm::ivec2 plotSize = parseImageSizeOption(options->plotSize, "--size", 320, 8192);
                if (!options->plot.empty()) requireWritableImagePath(options->plot, "-o");
                const Series series = openDataset(*inputs, *dataset);
                const ProbePlaces places = placesOf(*options, series);
                const TemporalProbe probe(series);
                std::vector<std::vector<std::optional<double>>> values;  // per place, per time-step
                for (const glm::dvec3& point : places.points) values.push_back(probe.valuesAt(point));
                requireSomeGridMet(series, places, values);
                std::vector<double> times;
                for (const TimeStep& step : series.steps) times.push_back(step.time);
                const std::vector<std::string> labels = formatTimes(times, series.time);
                if (options->json) writeJson(series, places, labels, values);
                else if (options->csv) writeCsv(series, places, labels, values);
                else writeText(series, places, labels, values);
                if (!options->plot.empty()) {
                    ProbeTable table = tableOf(series, places, labels, values);
                    if (!places.line) table.timeColours = automaticTimeColours(series);
                    writeImage(drawProbePlot(table, plotSize), options->plot);
                    std::cerr << "wrote " << options->plot.string() << "\n";
                }
                return kExitSuccess;
            }};
}

}  // namespace tstyles::cli
