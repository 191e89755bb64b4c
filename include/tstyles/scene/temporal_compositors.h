// The table of temporal compositors: one line each, with its scene-file name, its shader module
// (shaders/tc_*.glsl), the transfer function that reads it and the options it takes. Adding a
// compositor is a module and a line here; adding an option is a CompositorOption in the line (and
// the uniform the module declares for it). The scene reader and writer, the scene key table (and so
// the docs, animation tracks and Python), the window, `--tc` and the legends all follow the table.
#pragma once

#include <array>
#include <cstddef>
#include <compare>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "tstyles/core/interval.h"

namespace tstyles {

struct Scene;

// Which transfer function reads a compositor's temporal characteristic.
enum class CompositorReads {
    IndexTstf,     // a time-step index
    GradientTstf,  // a value in density units, through the gradient TSTF's range
    Composited,    // each time-step is styled on its own and the results are combined
};

// How an automatic ("auto") gradient TSTF range fits a compositor's characteristic, from the
// series' typical largest change over time C (typicalLargestChange) and its time span T.
enum class AutomaticRange {
    Change,          // [0, C]
    HalfChange,      // [0, C / 2]: a standard deviation of values spread over C is at most C / 2
    SignedChange,    // [-C, C]
    SignedPerTime,   // [-C / T, C / T]: the slope of a change of C over the whole series
};

// What an option holds, and so its JSON, its uniform and its widget in the window.
enum class CompositorOptionKind {
    Number,        // a number in `range`: a float uniform; a slider over the range
    TimeStepPair,  // [from, to], time-step indices of the series, `to` by default the last: an ivec2
                   // uniform; two time-step sliders
    Choice,        // one of `choices` by name, the first the default: an int uniform, the choice's
                   // place; a list to pick from
};

// An option a compositor takes: "compositor": {"name": ..., KEY: value} in a scene file, the scene
// key "compositor.KEY". Compositors that take options of one key take the same option.
struct CompositorOption {
    const char* key = "";
    CompositorOptionKind kind = CompositorOptionKind::Number;
    const char* uniform = "";  // declared by the module of every compositor that takes the option
    const char* help = "";     // the docs' key table and the window's tooltip
    Interval range = unitInterval;  // Number: the values taken (finite: the window's slider spans it)
    double defaultNumber = 0.0;     // Number
    std::array<const char*, 4> choices{};  // Choice: the names, the first the default

    constexpr std::size_t choiceCount() const {
        std::size_t count = 0;
        while (count < choices.size() && choices[count] != nullptr) ++count;
        return count;
    }
    // The place of a choice's name, none for another name.
    std::optional<std::size_t> choiceNamed(std::string_view name) const;
    std::vector<std::string> choiceNames() const;
};

inline constexpr std::size_t kMaxCompositorOptions = 3;

// A compositor's options, written in its table line as {kThresholdOption, CompositorOption{...}}.
class CompositorOptionList {
public:
    constexpr CompositorOptionList() = default;
    template <class... Options>
    constexpr CompositorOptionList(const Options&... options) : options_{options...}, count_(sizeof...(Options)) {
        static_assert(sizeof...(Options) <= kMaxCompositorOptions, "raise kMaxCompositorOptions");
    }
    constexpr const CompositorOption* begin() const { return options_.data(); }
    constexpr const CompositorOption* end() const { return options_.data() + count_; }
    constexpr bool empty() const { return count_ == 0; }
    // The option of `key`, or null where the compositor does not take it.
    const CompositorOption* find(std::string_view key) const;

private:
    std::array<CompositorOption, kMaxCompositorOptions> options_{};
    std::size_t count_ = 0;
};

struct TemporalCompositorInfo {
    const char* name = "";          // in scene files, --tc and the viewer
    const char* shaderModule = "";  // in shaders/; empty for the scene's own (the "custom" line)
    CompositorReads reads = CompositorReads::IndexTstf;
    // GradientTstf (and the scene's own code, whichever TSTF reads it): what "auto" fits.
    AutomaticRange range = AutomaticRange::Change;
    const char* valueName = "value";                // GradientTstf: what the legend calls the value
    bool takesUnchanged = false;  // picks a time-step: CompositorOptions::unchanged applies
    CompositorOptionList options = {};
    const char* summary = "";  // one line for help texts, the viewer and the docs' table
};

// The options shared by several compositors.
inline constexpr CompositorOption kThresholdOption{
    .key = "threshold",
    .kind = CompositorOptionKind::Number,
    .uniform = "compositorThreshold",
    .help = "the density a time-step must reach at the sample",
    .range = unitInterval,
    .defaultNumber = 0.5,
};

// The compositors (paper 5.3, and the ones users of temporal data ask for), in the order the CLI,
// the window and the docs list them. The first is the default; "custom" is the scene's own GLSL.
inline constexpr std::array kTemporalCompositors = [] {
    using enum CompositorReads;
    using enum AutomaticRange;
    using Info = TemporalCompositorInfo;
    return std::array{
        Info{.name = "temporal-mip", .shaderModule = "tc_max_intensity_projection.glsl", .reads = IndexTstf,
             .takesUnchanged = true, .summary = "the time-step with the highest STF opacity, by the index TSTF"},
        Info{.name = "temporal-average", .shaderModule = "tc_average.glsl", .reads = Composited,
             .summary = "colours and opacities averaged over the visible time-steps"},
        Info{.name = "temporal-max-change", .shaderModule = "tc_max_density_change.glsl", .reads = GradientTstf,
             .valueName = "change", .summary = "largest minus smallest density, by the gradient TSTF"},
        Info{.name = "temporal-min", .shaderModule = "tc_minimum.glsl", .reads = IndexTstf, .takesUnchanged = true,
             .summary = "the time-step with the lowest density, by the index TSTF"},
        Info{.name = "temporal-std-dev", .shaderModule = "tc_standard_deviation.glsl", .reads = GradientTstf,
             .range = HalfChange, .valueName = "standard deviation",
             .summary = "standard deviation of the densities, by the gradient TSTF"},
        Info{.name = "time-of-max", .shaderModule = "tc_time_of_maximum.glsl", .reads = IndexTstf,
             .takesUnchanged = true,
             .summary = "the time-step of the highest density (time to peak), by the index TSTF"},
        Info{.name = "first-arrival", .shaderModule = "tc_first_arrival.glsl", .reads = IndexTstf,
             .takesUnchanged = true, .options = {kThresholdOption},
             .summary = "the first time-step at or above the threshold, by the index TSTF"},
        Info{.name = "last-above", .shaderModule = "tc_last_above.glsl", .reads = IndexTstf, .takesUnchanged = true,
             .options = {kThresholdOption},
             .summary = "the last time-step at or above the threshold, by the index TSTF"},
        Info{.name = "threshold-crossing", .shaderModule = "tc_threshold_crossing.glsl", .reads = IndexTstf,
             .takesUnchanged = true,
             .options = {kThresholdOption,
                         CompositorOption{
                             .key = "direction",
                             .kind = CompositorOptionKind::Choice,
                             .uniform = "compositorDirection",
                             .help = "\"rising\": the first time-step at or above the threshold after one below it; "
                                     "\"falling\": the first below it after one at or above it",
                             .choices = {"rising", "falling"},
                         }},
             .summary = "the first time-step at which the density crosses the threshold (rising or falling), by the "
                        "index TSTF"},
        Info{.name = "linear-trend", .shaderModule = "tc_linear_trend.glsl", .reads = GradientTstf,
             .range = SignedPerTime, .valueName = "trend",
             .summary = "least-squares slope of density over time, by the gradient TSTF"},
        Info{.name = "chronovolume", .shaderModule = "tc_chronovolume.glsl", .reads = Composited,
             .summary = "the time-steps composited front to back in time order"},
        Info{.name = "difference", .shaderModule = "tc_difference.glsl", .reads = GradientTstf,
             .range = SignedChange, .valueName = "difference",
             .options = {CompositorOption{
                 .key = "steps",
                 .kind = CompositorOptionKind::TimeStepPair,
                 .uniform = "compositorSteps",
                 .help = "the time-steps [from, to] whose difference density(to) - density(from) shows",
             }},
             .summary = "density of one time-step minus another's, by the gradient TSTF"},
        Info{.name = "custom", .reads = IndexTstf, .summary = "the scene's own GLSL over the time-steps at the sample"},
    };
}();

// A compositor: its line in kTemporalCompositors.
class TemporalCompositor {
public:
    constexpr TemporalCompositor() = default;  // the first line, temporal-mip
    constexpr explicit TemporalCompositor(std::size_t line) : line_(line) {}
    constexpr std::size_t line() const { return line_; }
    constexpr auto operator<=>(const TemporalCompositor&) const = default;

private:
    std::size_t line_ = 0;
};

// The compositor of a name, at compile time: a name the table lacks does not compile.
consteval TemporalCompositor compositorNamed(std::string_view name) {
    for (std::size_t line = 0; line < kTemporalCompositors.size(); ++line)
        if (std::string_view(kTemporalCompositors[line].name) == name) return TemporalCompositor(line);
    throw std::invalid_argument("no temporal compositor of this name");
}

inline constexpr TemporalCompositor kCustomCompositor = compositorNamed("custom");

std::span<const TemporalCompositorInfo> temporalCompositors();
const TemporalCompositorInfo& compositorInfo(TemporalCompositor compositor);
std::string toString(TemporalCompositor compositor);
std::optional<TemporalCompositor> temporalCompositorFromString(const std::string& name);
// Every compositor a scene file, --tc and the window name, in the table's order: all but the
// custom compositor, which needs its code.
std::vector<TemporalCompositor> builtInCompositors();
// Their names.
std::vector<std::string> temporalCompositorNames();
// What reads the scene's compositor: the table's line, or the custom compositor's own choice.
CompositorReads compositorReads(const Scene& scene);

// Every option of the table once (compositors share an option by its key), in the table's order.
std::vector<const CompositorOption*> compositorOptionsOfAll();
// The names of the compositors that take the option of `key`, and of those whose line says
// `takesUnchanged`.
std::vector<std::string> compositorsTaking(std::string_view key);
std::vector<std::string> compositorsTakingUnchanged();
// The markdown table of docs/compositors.md's list of compositors, made from the table; it stands
// between these two lines there (build/tools/write_doc_tables docs writes it).
std::string compositorDocTable();
inline constexpr const char* kCompositorTableBegin =
    "<!-- The table of compositors is generated from include/tstyles/scene/temporal_compositors.h: "
    "build/tools/write_doc_tables docs -->";
inline constexpr const char* kCompositorTableEnd = "<!-- End of the generated table of compositors. -->";

// Names as a sentence lists them, each between `quote`s: "a, b and c", "`a` and `b`".
std::string listedNames(const std::vector<std::string>& names, std::string_view quote = "");

}  // namespace tstyles
