// The reader options' table (reader_option_table.h): one line per option.
#include "tstyles/data/reader_option_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "readers/format_table.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

constexpr double kLargestWholeNumber = double(std::numeric_limits<int>::max());

const std::string& lastGiven(const std::vector<std::string>& texts) { return texts.back(); }

std::vector<ReaderOptionLine> buildLines() {
    using Kind = ReaderOptionKind;
    std::vector<ReaderOptionLine> lines;
    lines.push_back({"var", "--var", "var", Kind::Text, "NAME", 0, 0, false, {}, "",
                     "NetCDF: the variable to read; Plot3D: density, x-momentum, y-momentum, z-momentum, energy, "
                     "momentum-magnitude, pressure, or function-K for function (.f) files; VTK: the point-data "
                     "array (a vector is read as its magnitude)",
                     false, [](ReadOptions& o, const auto& t, const auto&) { o.variable = lastGiven(t); },
                     [](const ReadOptions& o) { return !o.variable.empty(); }});
    lines.push_back({"time-dim", "--time-dim", "time_dim", Kind::Text, "NAME", 0, 0, false, {}, "",
                     "NetCDF: the time dimension, when it is not found", false,
                     [](ReadOptions& o, const auto& t, const auto&) { o.timeDimension = lastGiven(t); },
                     [](const ReadOptions& o) { return !o.timeDimension.empty(); }});
    lines.push_back({"index-axes", "--index-axes", "index_axes", Kind::Flag, "", 0, 0, false, {}, "off",
                     "NetCDF: unit spacing instead of the coordinate variables", false,
                     [](ReadOptions& o, const auto&, const auto&) { o.indexAxes = true; },
                     [](const ReadOptions& o) { return o.indexAxes; }});
    lines.push_back({"steps", "--steps", "steps", Kind::Steps, "FIRST:END:STRIDE", 0, 0, false, {}, "every time-step",
                     "Time-steps FIRST:END:STRIDE (END exclusive, may be empty), e.g. 0:48:5", false,
                     [](ReadOptions& o, const auto& t, const auto& s) { o.steps = parseStepSelection(lastGiven(t), s); },
                     [](const ReadOptions& o) { return o.steps.has_value(); }});
    lines.push_back({"range", "--range", "value_range", Kind::ValueRange, "LO:HI", 0, 0, false, {},
                     "the chosen steps' values", "Raw values LO:HI map to density 0 and 1 (default: the data's)", false, [](ReadOptions& o, const auto& t, const auto& s) { o.valueRange = parseValueRange(lastGiven(t), s); },
                     [](const ReadOptions& o) { return o.valueRange.has_value(); }});
    lines.push_back({"resample", "--resample", "resample", Kind::Dims, "NXxNYxNZ", 0, 0, false, {}, "",
                     "Resample every time-step to NXxNYxNZ (rectilinear grids)", false,
                     [](ReadOptions& o, const auto& t, const auto& s) { o.resampleTo = parseDims(lastGiven(t), s); },
                     [](const ReadOptions& o) { return o.resampleTo.has_value(); }});
    lines.push_back({"dims", "--dims", "dims", Kind::Dims, "NXxNYxNZ", 0, 0, false, {}, "500x500x100 (Isabel)",
                     "Hurricane Isabel raw files: samples per file NXxNYxNZ (default 500x500x100); plain TIFF: the "
                     "samples of one volume",
                     false, [](ReadOptions& o, const auto& t, const auto& s) { o.rawDims = parseDims(lastGiven(t), s); },
                     [](const ReadOptions& o) { return o.rawDims.has_value(); }});
    lines.push_back({"channel", "--channel", "channel", Kind::WholeNumber, "N", 0, kLargestWholeNumber, false, {}, "0",
                     "TIFF, OME-Zarr: which channel of a multi-channel image (samples of a pixel, channel planes, the c "
                     "axis), from 0; `info` says which", false,
                     [](ReadOptions& o, const auto& t, const auto&) { o.channel = std::stoi(lastGiven(t)); },
                     [](const ReadOptions& o) { return o.channel.has_value(); }});
    lines.push_back({"series", "--series", "series", Kind::Text, "N|N,M,...|all|UID", 0, 0, false, {},
                     "the most frames, or phases",
                     "DICOM: which series of the folder, by its number in `tstyles info`'s list (from 1) or its "
                     "SeriesInstanceUID; several numbers (2,3,4) or all read those series as the time-steps of one "
                     "(multi-phase CT, DCE-MR per phase). Default: the series with the most frames, or phases of "
                     "one study where they hold more",
                     false, [](ReadOptions& o, const auto& t, const auto&) { o.seriesChoice = lastGiven(t); },
                     [](const ReadOptions& o) { return !o.seriesChoice.empty(); }});
    lines.push_back({"axes", "--axes", "axes", Kind::Text, "TZYX|ZTYX", 0, 0, false, {}, "TZYX",
                     "Plain TIFF: what the pages are, slowest axis first, with --dims: TZYX (default) or ZTYX", false,
                     [](ReadOptions& o, const auto& t, const auto&) { o.pageAxes = lastGiven(t); },
                     [](const ReadOptions& o) { return !o.pageAxes.empty(); }});
    lines.push_back({"level", "--level", "level", Kind::WholeNumber, "N", 0, kLargestWholeNumber, false, {},
                     "the finest that fits (OME-Zarr), 0 (OME-TIFF)",
                     "OME-Zarr, OME-TIFF pyramids (SubIFDs): the resolution level, 0 the finest (default: OME-Zarr, "
                     "the finest that fits the memory limits; OME-TIFF, 0; `info` says which)",
                     false, [](ReadOptions& o, const auto& t, const auto&) { o.level = std::stoi(lastGiven(t)); },
                     [](const ReadOptions& o) { return o.level.has_value(); }});
    lines.push_back({"precision", "--precision", "precision", Kind::Choice, "BITS", 0, 0, false, {"8", "16", "32"}, "16",
                     "Bits per density on the GPU: 8, 16 (default) or 32 (R8, R16, R32F; RG8, RG16, RG32F with missing "
                     "values); counted by --max-memory", true,
                     [](ReadOptions& o, const auto& t, const auto& s) { o.precision = parseDensityPrecision(lastGiven(t), s); },
                     [](const ReadOptions& o) { return o.precision != ReadOptions{}.precision; }});
    lines.push_back({"max-memory", "--max-memory", "max_memory", Kind::MemorySize, "SIZE", 0, 0, false, {},
                     "half of this machine's memory",
                     "Memory the series may take (host + GPU copy), e.g. 512M, 2G or bytes; more is refused with the "
                     "figure it needs, or fitted (--fit)", true, [](ReadOptions& o, const auto& t, const auto& s) { o.maxMemoryBytes = parseMemorySize(lastGiven(t), s); },
                     [](const ReadOptions& o) { return o.maxMemoryBytes.has_value(); }});
    lines.push_back({"fit", "--fit", "fit", Kind::Choice, "HOW", 0, 0, false, {"refuse", "resolution", "steps"}, "refuse",
                     "With --max-memory, a series too large is: refuse (default), resolution (read smaller), steps "
                     "(fewer time-steps)",
                     false, [](ReadOptions& o, const auto& t, const auto& s) { o.fit = parseMemoryFit(lastGiven(t), s); },
                     [](const ReadOptions& o) { return o.fit != MemoryFit::Refuse; }});
    lines.push_back({"solution", "--solution", "solution", Kind::Files, "FILE,...", 0, 0, false, {}, "",
                     "Plot3D: solution (.q) or function (.f) files, one per time-step in time order (comma-separated "
                     "or repeated); the dataset is then the grid file",
                     false,
                     [](ReadOptions& o, const auto& t, const auto&) {
                         o.solutionFiles.assign(t.begin(), t.end());
                     },
                     [](const ReadOptions& o) { return !o.solutionFiles.empty(); }});
    lines.push_back({"block", "--block", "block", Kind::WholeNumber, "N", 0, kLargestWholeNumber, false, {}, "0",
                     "Plot3D: which block of a multi-block file (from 0)", false,
                     [](ReadOptions& o, const auto& t, const auto&) { o.block = std::stoi(lastGiven(t)); },
                     [](const ReadOptions& o) { return o.block != ReadOptions{}.block; }});
    lines.push_back({"gamma", "--gamma", "gamma", Kind::Number, "G", 1.0, 10.0, true, {}, "1.4",
                     "Plot3D: ratio of specific heats, for pressure", false,
                     [](ReadOptions& o, const auto& t, const auto&) { o.gamma = std::stod(lastGiven(t)); },
                     [](const ReadOptions& o) { return o.gamma != ReadOptions{}.gamma; }});
    return lines;
}

std::string boundNumberText(double value) {
    if (value == kLargestWholeNumber) return std::to_string(std::numeric_limits<int>::max());
    std::ostringstream text;
    text << value;
    return text.str();
}

std::string inQuotes(const std::string& text) { return "\"" + text + "\""; }

// Which readers take a line: the formats whose rows name it, or every one (and a manifest).
std::string formatsReading(const ReaderOptionLine& line) {
    if (!isFormatOnly(line)) return line.forManifest ? "every format and a manifest" : "every format";
    std::string formats;
    for (const SeriesFormat& format : seriesFormats())
        if (std::find(format.options.begin(), format.options.end(), line.cli) != format.options.end())
            formats += (formats.empty() ? "" : ", ") + format.name;
    return formats;
}

}  // namespace

bool isFormatOnly(const ReaderOptionLine& line) {
    for (const SeriesFormat& format : seriesFormats())
        if (std::find(format.options.begin(), format.options.end(), line.cli) != format.options.end()) return true;
    return false;
}

const std::vector<ReaderOptionLine>& readerOptionLines() {
    static const std::vector<ReaderOptionLine> lines = buildLines();
    return lines;
}

const ReaderOptionLine* readerOptionNamed(std::string_view name) {
    for (const ReaderOptionLine& line : readerOptionLines())
        if (line.cli == name || line.key == name || line.python == name) return &line;
    return nullptr;
}

std::string readerOptionBounds(const ReaderOptionLine& line) {
    switch (line.kind) {
        case ReaderOptionKind::WholeNumber:
        case ReaderOptionKind::Number: {
            const std::string kind = line.kind == ReaderOptionKind::WholeNumber ? "a whole number " : "a number ";
            const std::string low = (line.lowExclusive ? "above " : "") + boundNumberText(line.low);
            if (line.high == kLargestWholeNumber)
                return kind + low + (line.lowExclusive ? "" : " or more");
            return kind + (line.lowExclusive ? low + " and at most " : "from " + low + " to ") + boundNumberText(line.high);
        }
        case ReaderOptionKind::Choice: {
            std::string text;
            for (std::size_t i = 0; i < line.choices.size(); ++i)
                text += (i == 0 ? "" : i + 1 == line.choices.size() ? " or " : ", ") + std::string(line.choices[i]);
            return text;
        }
        default: return "";
    }
}

void checkReaderOptionText(const ReaderOptionLine& line, const std::string& text) {
    const std::string spelling(line.cli);
    const auto refuse = [&] {
        throwInputError("", spelling, "must be " + readerOptionBounds(line) + "; got " + inQuotes(text));
    };
    switch (line.kind) {
        case ReaderOptionKind::WholeNumber: {
            const bool digits = !text.empty() && text.size() <= 10 &&
                                std::all_of(text.begin() + (text[0] == '-' ? 1 : 0), text.end(),
                                            [](char c) { return c >= '0' && c <= '9'; }) &&
                                text != "-";
            if (!digits) refuse();
            const double value = std::stod(text);
            if (value < line.low || value > line.high) refuse();
            return;
        }
        case ReaderOptionKind::Number: {
            std::size_t used = 0;
            double value = std::numeric_limits<double>::quiet_NaN();
            try {
                value = std::stod(text, &used);
            } catch (const std::exception&) {
                refuse();
            }
            if (used != text.size() || !std::isfinite(value)) refuse();
            if (line.lowExclusive ? value <= line.low : value < line.low) refuse();
            if (value > line.high) refuse();
            return;
        }
        case ReaderOptionKind::Choice:
            if (std::find(line.choices.begin(), line.choices.end(), text) == line.choices.end()) refuse();
            return;
        default: return;
    }
}

ReadOptions readOptionsFrom(const ReaderOptionTexts& texts) {
    ReadOptions options;
    for (const auto& [key, values] : texts) {
        const ReaderOptionLine* line = readerOptionNamed(key);
        if (line == nullptr || line->key != key) throwInputError("", key, "is not a reader option");
        if (values.empty()) throwInputError("", std::string(line->cli), "was given no value");
        if (line->kind != ReaderOptionKind::Files)
            if (values.size() > 1) throwInputError("", std::string(line->cli), "was given more than once");
        for (const std::string& value : values) checkReaderOptionText(*line, value);
        line->set(options, values, std::string(line->cli));
    }
    if (options.fit != MemoryFit::Refuse && !options.maxMemoryBytes)
        throwInputError("", "--fit", "says what to do over --max-memory, which is not given");
    return options;
}

std::vector<const ReaderOptionLine*> readerOptionsGiven(const ReadOptions& options) {
    std::vector<const ReaderOptionLine*> given;
    for (const ReaderOptionLine& line : readerOptionLines())
        if (line.given(options)) given.push_back(&line);
    return given;
}

std::string readerOptionsMarkdown() {
    std::string table =
        "| Option | Python keyword | Value | Default | Read by | Meaning |\n|---|---|---|---|---|---|\n";
    const auto escaped = [](std::string_view text) {
        std::string out;
        for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
        return out;
    };
    for (const ReaderOptionLine& line : readerOptionLines()) {
        std::string value = line.valueName.empty() ? "(a flag)" : "`" + escaped(line.valueName) + "`";
        if (const std::string bounds = readerOptionBounds(line); !bounds.empty()) value += ": " + bounds;
        table += "| `" + std::string(line.cli) + "` | `" + std::string(line.python) + "` | " + value + " | " +
                 (line.defaultText.empty() ? "" : escaped(line.defaultText)) + " | " + formatsReading(line) + " | " +
                 escaped(line.help) + " |\n";
    }
    return table;
}

}  // namespace tstyles
