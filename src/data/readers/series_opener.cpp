// Which reader: a manifest by its folder or .json, any other format by the format table.
#include "tstyles/core/ascii_case.h"
#include "tstyles/data/series_opener.h"

#include <algorithm>
#include <stdexcept>

#include "format_table.h"
#include "series_assembly.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/data/manifest.h"
#include "tstyles/data/reader_option_table.h"

namespace tstyles {
namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

const SeriesFormat& formatByName(const std::string& name) {
    for (const SeriesFormat& format : seriesFormats())
        if (format.name == name) return format;
    throw std::logic_error("no series format named " + name);
}

const SeriesFormat* formatByExtension(const std::filesystem::path& input) {
    const std::string name = lowercaseFileName(input);
    for (const SeriesFormat& format : seriesFormats())
        for (const std::string& extension : format.extensions)
            if (endsWith(name, extension)) return &format;
    return nullptr;
}

// The format that reads this folder as a whole, or null (a manifest's folder, or none).
const SeriesFormat* formatClaimingFolder(const std::filesystem::path& folder) {
    for (const SeriesFormat& format : seriesFormats())
        if (format.claimsFolder && format.claimsFolder(folder)) return &format;
    return nullptr;
}

// Solution files say the input is a Plot3D grid, whatever its name (unless it is named like
// another format); otherwise the extension decides, then the content. A folder is a format's when
// the format claims it.
const SeriesFormat& formatOf(const std::filesystem::path& input, const ReadOptions& options) {
    std::error_code error;
    if (userPathKind({}, input) == PathKind::Missing) throwInputError(input, "", "no such file or folder");
    if (std::filesystem::is_directory(input, error)) {
        if (const SeriesFormat* format = formatClaimingFolder(input)) return *format;
        throwInputError(input, "", "is a folder that holds no series.json and no series of a format this program reads");
    }
    // Sniffing reads the first bytes: a FIFO or device would block or never end.
    requireRegularFile(input, "data file");
    const SeriesFormat* byExtension = formatByExtension(input);
    if (!options.solutionFiles.empty()) {
        if (byExtension && byExtension->name != kPlot3DFormatName)
            throwInputError(input, "--solution",
                            "applies to Plot3D grid files, and this is named like a " + byExtension->name + " file");
        return formatByName(kPlot3DFormatName);
    }
    if (byExtension) return *byExtension;
    for (const SeriesFormat& format : seriesFormats())
        if (format.sniff && format.sniff(input)) return format;
    std::string known = "tstyles manifest (.json, or its folder)";
    for (const SeriesFormat& format : seriesFormats()) known += "; " + format.name + " (" + format.spelling + ")";
    throwInputError(input, "", "unknown format: its name and first bytes match none of " + known);
}

// A manifest is already prepared: the reading options have nothing to choose in it but the
// precision and the memory limit (the table's `forManifest`).
void rejectReadingOptions(const std::filesystem::path& manifest, const ReadOptions& options) {
    for (const ReaderOptionLine* line : readerOptionsGiven(options))
        if (!line->forManifest) {
            std::string takers;
            if (isFormatOnly(*line))
                for (const SeriesFormat& format : seriesFormats())
                    if (std::find(format.options.begin(), format.options.end(), line->cli) != format.options.end())
                        takers += (takers.empty() ? "" : ", ") + format.name;
            throwInputError(manifest, std::string(line->cli),
                            "applies to the files a reader reads" + (takers.empty() ? "" : " (" + takers + ")") +
                                ", not to a tstyles manifest");
        }
}

// The options that only some formats take, as the command line spells them, where given.
std::vector<std::string> formatOnlyOptionsGiven(const ReadOptions& options) {
    std::vector<std::string> given;
    for (const ReaderOptionLine* line : readerOptionsGiven(options))
        if (isFormatOnly(*line)) given.emplace_back(line->cli);
    return given;
}

// An option the format has no use for is an error, not silently ignored.
void rejectForeignOptions(const std::filesystem::path& input, const SeriesFormat& format, const ReadOptions& options) {
    for (const std::string& option : formatOnlyOptionsGiven(options))
        if (std::find(format.options.begin(), format.options.end(), option) == format.options.end()) {
            std::string takers;
            for (const SeriesFormat& other : seriesFormats())
                if (std::find(other.options.begin(), other.options.end(), option) != other.options.end())
                    takers += (takers.empty() ? "" : " and ") + other.name;
            throwInputError(input, option, "does not apply to " + format.name + " files (only to " + takers + ")");
        }
}

SourceSeries openSource(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options) {
    const SeriesFormat& format = formatOf(inputs.front(), options);
    rejectForeignOptions(inputs.front(), format, options);
    for (const auto& input : inputs)
        if (&formatOf(input, options) != &format)
            throwInputError(input, "", "is not " + format.name + " like " + inputs.front().string() +
                                           ": a series is read from files of one format");
    // Named after the format; a reader that calls a library names the library and stage itself.
    reportStage(options.monitor, inputs.front(), "the " + format.name + " reader", "reading the header");
    return format.open(inputs, options);
}

}  // namespace

bool isManifestInput(const std::filesystem::path& input) {
    std::error_code error;
    if (std::filesystem::is_directory(input, error)) return formatClaimingFolder(input) == nullptr;
    // A Zarr v3 store's metadata file is JSON but names the store, not a manifest.
    return endsWith(lowercaseFileName(input), ".json") && lowercaseFileName(input) != "zarr.json";
}

bool isNamedLikeSeriesFile(const std::filesystem::path& input) { return formatByExtension(input) != nullptr; }

std::string formatNamedBy(const std::filesystem::path& input) {
    std::error_code error;
    if (std::filesystem::is_directory(input, error)) {
        if (const SeriesFormat* format = formatClaimingFolder(input)) return format->name;
        return std::filesystem::is_regular_file(input / "series.json", error) ? "tstyles manifest" : "";
    }
    const SeriesFormat* format = formatByExtension(input);
    return format ? format->name : "";
}

std::string seriesFormatName(const std::filesystem::path& input) {
    return isManifestInput(input) ? "tstyles manifest" : formatOf(input, {}).name;
}

Series openRawSeries(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options) {
    if (inputs.empty()) throw std::invalid_argument("openRawSeries: no input");
    for (const auto& input : inputs)
        if (isManifestInput(input))
            throwInputError(input, "", "is a tstyles manifest, not a file to read into one");
    const SourceSeries source = openSource(inputs, options);
    Series series = assembleRawSeries(source, options);
    series.precision = options.precision;
    series.sourceFormat = source.format;
    series.readingNotes.insert(series.readingNotes.end(), source.notes.begin(), source.notes.end());
    return series;
}

Series openSeries(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options) {
    if (inputs.empty()) throw std::invalid_argument("openSeries: no input");
    if (isManifestInput(inputs.front())) {
        if (inputs.size() > 1)
            throwInputError(inputs[1], "", "a tstyles manifest is a whole series: give it alone");
        rejectReadingOptions(inputs.front(), options);
        ManifestLimits limits{options.maxMemoryBytes, bytesPerDensity(options.precision)};
        if (ReadingMonitor* monitor = options.monitor) {
            monitor->enterStage(inputs.front(), "the manifest reader", "reading the manifest and its files");
            limits.afterStepRead = [monitor](std::size_t, TimeStep& step) {
                monitor->stepRead(step.density.size() * sizeof(float));
            };
        }
        Series series = loadSeries(inputs.front(), limits);
        series.precision = options.precision;
        return series;
    }
    return toDensity(openRawSeries(inputs, options));
}

Series openSeries(const std::filesystem::path& input, const ReadOptions& options) {
    return openSeries(std::vector<std::filesystem::path>{input}, options);
}

}  // namespace tstyles
