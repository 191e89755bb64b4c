// The table of ray modes: how the samples along a ray become the pixel, one line each, with its
// scene-file name, its shader module (shaders/ray_*.glsl) and the options it takes. The temporal
// compositor turns the time-steps at each sample into a characteristic; the ray mode reduces those
// along the ray (composite front to back, the paper's; maximum; minimum; average; additive;
// attenuated maximum; largest change; iso-surfaces). Adding a mode is a module and a line here; adding an option is
// a RayModeOption in the line (and the uniform the module declares for it). The scene reader and
// writer, the scene key table (and so the docs and Python), the window, `--ray` and its
// `--ray-KEY` options and the legend follow the table.
#pragma once

#include <array>
#include <compare>
#include <cstddef>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "tstyles/core/interval.h"

namespace tstyles {

// What a ray mode's option holds, and so its JSON, its uniform and its widget in the window.
enum class RayModeOptionKind {
    Number,      // a number in `range`: a float uniform; a slider
    NumberList,  // 1 to `maxCount` numbers, each in `range`: a vec4 uniform, padded with `padding`;
                 // a slider per number
};

struct RayModeOption {
    const char* key = "";
    RayModeOptionKind kind = RayModeOptionKind::Number;
    const char* uniform = "";  // declared by the mode's module
    const char* help = "";     // the docs' key table and the window's tooltip
    Interval range = unitInterval;
    double defaultNumber = 0.0;  // Number; NumberList: each entry's default
    // NumberList: at most this many entries (the vec4 holds 4), the value of the unused ones in
    // the uniform, and the key of another list whose length this one must have (its entries then
    // default to defaultNumber each); null: one entry, defaultNumber, by default.
    std::size_t maxCount = 1;
    double padding = 0.0;
    const char* countOf = nullptr;
};

inline constexpr std::size_t kMaxRayModeOptions = 2;

class RayModeOptionList {
public:
    constexpr RayModeOptionList() = default;
    template <class... Options>
    constexpr RayModeOptionList(const Options&... options) : options_{options...}, count_(sizeof...(Options)) {
        static_assert(sizeof...(Options) <= kMaxRayModeOptions, "raise kMaxRayModeOptions");
    }
    constexpr const RayModeOption* begin() const { return options_.data(); }
    constexpr const RayModeOption* end() const { return options_.data() + count_; }
    constexpr bool empty() const { return count_ == 0; }
    const RayModeOption* find(std::string_view key) const;

private:
    std::array<RayModeOption, kMaxRayModeOptions> options_{};
    std::size_t count_ = 0;
};

// How the frames of blocks that processes rendered merge into one (distributed rendering,
// docs/scaling.md): the over operator in the ray's order, or none (the mode renders on one process).
enum class RayMerge {
    Over,        // premultiplied colours in visibility order
    None,        // a process's part of the ray reduced on its own does not merge: not distributed
};

// The STF the automatic scene gives a mode (applyAutomaticRay): how much opacity one sample needs.
enum class AutomaticStf {
    RayThrough,     // the histogram's ramp, peaking where a ray through the data gathers ~95 %; shaded
    LargestValue,   // one sample makes the pixel: a ramp to 1 at the largest value; unshaded, unchanged
                    // places at the STF's whole opacity
    EveryPlace,     // one sample makes the pixel, whatever its value: 1 from the 5th percentile up;
                    // unshaded, unchanged places a faint grey (the mode picks by change, not value)
};

// Where the window's probe lands on a pixel's ray (docs/probe.md): at the sample the pixel shows,
// estimated on the CPU from the STF (viewer/volume_picking.h).
enum class ProbeDepth {
    HalfOpacity,    // where the opacity gathered along the ray first passes one half
    LargestValue,   // the sample of the largest density the STF shows
    SmallestValue,  // the sample of the smallest density the STF shows
    LargestChange,  // the sample whose densities change most over the time-steps
    FirstCrossing,  // the first crossing of an iso-value by some time-step's density
};

struct RayModeInfo {
    const char* name = "";          // in scene files, --ray and the window
    const char* shaderModule = "";  // in shaders/
    // Reduces the characteristic's value along the ray (the maximum, an iso-value's crossing):
    // compositors that composite the time-steps' colours (CompositorReads::Composited) have none.
    bool needsValue = false;
    // The ray may end before its exit (nothing further changes the pixel).
    bool stopsEarly = false;
    // The pixel is as opaque as the STF makes one sample (or their mean), not a ray through all
    // of them: the automatic STF then rises to 1 (applyAutomaticRayOpacity).
    bool pixelTakesStfOpacity = false;
    // Compares how much each place changes over time: the range of its time-steps' densities,
    // which the built-in compositors that pick a time-step measure (CompositorInfo::takesUnchanged;
    // they measure it whether or not the scene asks for unchanged places, and the scene's own
    // index compositor is refused), or the magnitude of the value the gradient TSTF reads.
    bool readsChange = false;
    AutomaticStf automaticStf = AutomaticStf::RayThrough;
    // The automatic scene's ray step in typical cells of the data's grids (automaticStep): a whole
    // one where the samples are composited with their opacity corrected to the step, so that the
    // picture barely moves with it; half where the pixel is one sample's, which a coarser step can
    // step over (a maximum projection of an MR slab at one cell: SSIM 0.959 against half).
    double automaticStepInCells = 0.5;
    ProbeDepth probeDepth = ProbeDepth::HalfOpacity;
    RayMerge merge = RayMerge::Over;
    RayModeOptionList options = {};
    const char* summary = "";  // one line for help texts, the viewer and the docs' table
};

// The ray modes, in the order the CLI, the window and the docs list them; the first is the default.
inline constexpr std::array kRayModes = [] {
    using Info = RayModeInfo;
    return std::array{
        Info{.name = "composite", .shaderModule = "ray_composite.glsl", .stopsEarly = true,
             .automaticStepInCells = 1.0, .merge = RayMerge::Over,
             .summary = "the samples' temporal styles composited front to back (emission and absorption, the "
                        "paper's); rays stop once nearly opaque"},
        Info{.name = "maximum", .shaderModule = "ray_maximum.glsl", .needsValue = true,
             .pixelTakesStfOpacity = true, .automaticStf = AutomaticStf::LargestValue,
             .probeDepth = ProbeDepth::LargestValue, .merge = RayMerge::None,
             .summary = "the sample of the largest value along the ray (maximum intensity projection), in its "
                        "time colour"},
        Info{.name = "minimum", .shaderModule = "ray_minimum.glsl", .needsValue = true,
             .pixelTakesStfOpacity = true, .automaticStf = AutomaticStf::LargestValue,
             .probeDepth = ProbeDepth::SmallestValue, .merge = RayMerge::None,
             .summary = "the sample of the smallest value the STF shows along the ray, in its time colour"},
        Info{.name = "average", .shaderModule = "ray_average.glsl", .pixelTakesStfOpacity = true,
             .automaticStf = AutomaticStf::LargestValue, .merge = RayMerge::None,
             .summary = "the mean of the samples' temporal styles along the ray"},
        Info{.name = "additive", .shaderModule = "ray_additive.glsl", .stopsEarly = true, .merge = RayMerge::None,
             .summary = "the samples' temporal styles added up along the ray (emission without absorption)"},
        Info{.name = "attenuated-maximum", .shaderModule = "ray_attenuated_maximum.glsl", .needsValue = true,
             .pixelTakesStfOpacity = true, .automaticStf = AutomaticStf::LargestValue,
             .probeDepth = ProbeDepth::LargestValue, .merge = RayMerge::None,
             .options = {RayModeOption{
                 .key = "attenuation",
                 .kind = RayModeOptionKind::Number,
                 .uniform = "rayAttenuation",
                 .help = "how strongly the opacity in front of a sample lowers its value: 0 is the plain maximum",
                 .range = Interval{0.0, 10.0},
                 .defaultNumber = 1.0,
             }},
             .summary = "the largest value along the ray, each value first lowered by the opacity in front of it"},
        Info{.name = "largest-change", .shaderModule = "ray_largest_change.glsl", .needsValue = true,
             .pixelTakesStfOpacity = true, .readsChange = true, .automaticStf = AutomaticStf::EveryPlace,
             .probeDepth = ProbeDepth::LargestChange, .merge = RayMerge::None,
             .summary = "the sample whose values change most over time along the ray, in the colour of its "
                        "time-step: seen from above, each place of a map at the depth where it changes most"},
        Info{.name = "isosurface", .shaderModule = "ray_isosurface.glsl", .needsValue = true, .stopsEarly = true,
             .probeDepth = ProbeDepth::FirstCrossing, .merge = RayMerge::None,
             .options = {RayModeOption{
                             .key = "values",
                             .kind = RayModeOptionKind::NumberList,
                             .uniform = "isoValues",
                             .help = "the iso-values whose surfaces show, in the compositor's value (densities for "
                                     "the compositors that pick a time-step)",
                             .range = Interval{-1.0, 1.0},
                             .defaultNumber = 0.5,
                             .maxCount = 4,
                             .padding = 1.0e30,
                         },
                         RayModeOption{
                             .key = "opacities",
                             .kind = RayModeOptionKind::NumberList,
                             .uniform = "isoOpacities",
                             .help = "each surface's opacity, one per value",
                             .range = unitInterval,
                             .defaultNumber = 1.0,
                             .maxCount = 4,
                             .padding = 0.0,
                             .countOf = "values",
                         }},
             .summary = "the surfaces where the value crosses the iso-values, lit, composited front to back"},
    };
}();

// A ray mode: its line in kRayModes.
class RayMode {
public:
    constexpr RayMode() = default;  // the first line, composite
    constexpr explicit RayMode(std::size_t line) : line_(line) {}
    constexpr std::size_t line() const { return line_; }
    constexpr auto operator<=>(const RayMode&) const = default;

private:
    std::size_t line_ = 0;
};

consteval RayMode rayModeNamed(std::string_view name) {
    for (std::size_t line = 0; line < kRayModes.size(); ++line)
        if (std::string_view(kRayModes[line].name) == name) return RayMode(line);
    throw std::invalid_argument("no ray mode of this name");
}

inline constexpr RayMode kCompositeRay = rayModeNamed("composite");

std::span<const RayModeInfo> rayModes();
const RayModeInfo& rayModeInfo(RayMode mode);
std::string toString(RayMode mode);
std::optional<RayMode> rayModeFromString(const std::string& name);
std::vector<RayMode> allRayModes();
std::vector<std::string> rayModeNames();
// Every option of the table once, in the table's order; the names of the modes that take `key`.
std::vector<const RayModeOption*> rayModeOptionsOfAll();
std::vector<std::string> rayModesTaking(std::string_view key);
// The markdown table of docs/ray-modes.md's list of modes, made from the table; it stands between
// these two lines there (build/tools/write_doc_tables docs writes it).
std::string rayModeDocTable();
inline constexpr const char* kRayModeTableBegin =
    "<!-- The table of ray modes is generated from include/tstyles/scene/ray_modes.h: "
    "build/tools/write_doc_tables docs -->";
inline constexpr const char* kRayModeTableEnd = "<!-- End of the generated table of ray modes. -->";

}  // namespace tstyles
