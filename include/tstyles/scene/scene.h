// A scene: which dataset, seen how, classified how. The same JSON drives `tstyles render` and the viewer.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/display_frame.h"
#include "tstyles/scene/animation.h"
#include "tstyles/scene/annotations.h"
#include "tstyles/scene/camera.h"
#include "tstyles/scene/ray_modes.h"
#include "tstyles/scene/temporal_compositors.h"
#include "tstyles/scene/transfer_function.h"

namespace tstyles {

// A scene's own compositor: a GLSL function body over the documented inputs (docs/compositors.md).
struct CustomCompositor {
    std::string glsl;
    // Where the code came from, for messages: the scene file (inline "glsl"), or the file the scene
    // names ("file", then `ownFile`).
    std::filesystem::path origin;
    bool ownFile = false;
    CompositorReads reads = CompositorReads::IndexTstf;
    bool operator==(const CustomCompositor&) const = default;
};

// Time shown only where time shows something: where a place's densities change over the time-steps
// by no more than `below`, or where the time-step a compositor picks is ahead of another by no more
// than `tie`, the place shows no time colour (docs/compositors.md, "Unchanged places").
struct UnchangedTime {
    // Fitted to the data ("auto": unchangedFitOf, by fitAutomaticParts); `below` and `tie` then hold the fit.
    bool automatic = true;
    double below = 0.0;  // a change in density units, [0, 1]
    double tie = 0.0;    // a difference in density units, [0, 1]: 0 leaves only exact ties
    // Fitted: `below` and `tie` per band of density (contract::UNCHANGED_DENSITY_BANDS equal bands
    // over [0, 1], by the density of the time-step a compositor picks), for data whose noise
    // depends on the value; empty: `below` and `tie` everywhere.
    std::vector<double> belowByDensity;
    std::vector<double> tieByDensity;
    // An unchanged place shows the STF alone (no time colour) with this share of its opacity, in
    // [0, 1]: 1 as the STF has it, 0 transparent, between a faint neutral ghost.
    double opacity = 1.0;
    // A place that changes shows as if `gain` times as thick ([1, 8]): the STF's opacity is fitted to
    // rays through all of the visible data, and the changing part of it is thinner.
    double gain = 1.0;
    // Boundaries: an unchanged place keeps its share of opacity in full where the value gradient is
    // this steep (density per display length), less in proportion where it is flatter, so that
    // regions of one value fade and their boundaries stay; 0 everywhere in full.
    double boundary = 0.0;
    bool operator==(const UnchangedTime&) const = default;
};

// A value of a compositor's option, of its kind (CompositorOptionKind): a number, time-steps, a
// choice's name.
struct TimeStepPair {
    int from = 0;
    std::optional<int> to;  // none: the series' last time-step
    bool operator==(const TimeStepPair&) const = default;
};
using CompositorOptionValue = std::variant<double, TimeStepPair, std::string>;

// The settings of the scene's compositor.
struct CompositorOptions {
    // The table's options (temporal_compositors.h) by key: a value of the option's kind, or none for
    // its default. They stay when the compositor changes: compositors that take an option share it.
    std::map<std::string, CompositorOptionValue, std::less<>> values;
    std::optional<CustomCompositor> custom;
    // The compositors that pick a time-step (TemporalCompositorInfo::takesUnchanged): none shows
    // time colours everywhere, as the paper does.
    std::optional<UnchangedTime> unchanged;
    // Equal when every option of the table has the same value, given or by default.
    bool operator==(const CompositorOptions& other) const;

    // A Number option's value; a Choice option's place in its choices; a TimeStepPair option's
    // time-steps, `to` none for the last.
    double number(const CompositorOption& option) const;
    std::size_t choice(const CompositorOption& option) const;
    TimeStepPair timeSteps(const CompositorOption& option) const;
    // A TimeStepPair option's [from, to] on a series of `stepCount` time-steps; an InputError naming
    // "compositor.KEY[i]" of `sceneFile` where they do not fit it.
    glm::ivec2 timeStepsOn(const CompositorOption& option, std::size_t stepCount,
                           const std::filesystem::path& sceneFile = {}) const;

private:
    // The value given for `option` (of its kind's type T), or null for its default.
    template <class T>
    const T* givenValue(const CompositorOption& option) const {
        const auto found = values.find(std::string_view(option.key));
        return found == values.end() ? nullptr : std::get_if<T>(&found->second);
    }
};

// The settings of the scene's ray mode: the table's options (ray_modes.h) by key, a value of the
// option's kind (a number, a list of numbers), or none for its default. They stay when the mode
// changes, as the compositor's do.
using RayModeOptionValue = std::variant<double, std::vector<double>>;
struct RayModeOptions {
    std::map<std::string, RayModeOptionValue, std::less<>> values;
    // Equal when every option of the table has the same value, given or by default.
    bool operator==(const RayModeOptions& other) const;
    // A Number option's value; a NumberList option's entries (its defaults: one defaultNumber, or
    // as many as the list of `countOf` has).
    double number(const RayModeOption& option) const;
    std::vector<double> numbers(const RayModeOption& option) const;
};

// What the compositor returns: STF alone, TSTF alone, or the STF modulated by the TSTF.
enum class FinalMode { Stf, Tstf, Modulate };

std::string toString(FinalMode mode);
std::optional<FinalMode> finalModeFromString(const std::string& name);
// Every accepted name, in declaration order (for messages and UI lists).
std::vector<std::string> finalModeNames();

struct RaycastSettings {
    // World-space distance between samples; none means half the finest voxel spacing of the series.
    std::optional<double> step;
    // Rays stop once the accumulated opacity reaches this.
    double termination = 0.99;
    bool operator==(const RaycastSettings&) const = default;
};

// The time-steps that take part in the image, first and last inclusive: the paper's multiple
// exposure, narrowed or slid by an animation. No `last` means the series' last time-step.
struct Exposure {
    int first = 0;
    std::optional<int> last;
    bool operator==(const Exposure&) const = default;
    // What is wrong with "exposure.last" where it comes before first ("is 2, before exposure.first
    // (5)"), for every place that checks it: the reader, the series, an animation frame.
    std::optional<std::string> orderProblem() const;
    // [first, last] on a series of `stepCount` time-steps; an InputError naming "exposure.first" or
    // "exposure.last" of `sceneFile` where they do not fit it.
    glm::ivec2 stepsOf(std::size_t stepCount, const std::filesystem::path& sceneFile = {}) const;
};

// The most places a scene pins for the probe panel: each has its own colour and curve.
inline constexpr std::size_t kMaxProbes = 8;

struct Scene {
    // The series manifest. A file may name it relative to the scene file's folder; a loaded scene
    // holds the resolved absolute, normalized path. A relative path in memory means relative to the
    // current directory.
    std::filesystem::path dataset;
    // How the series' axes are turned and scaled for display (orientation, aspect, vertical
    // exaggeration); the default shows the data as stored.
    DisplaySettings display;
    Camera camera;
    int width = 512;
    int height = 512;
    glm::dvec4 background{0.0, 0.0, 0.0, 1.0};
    RaycastSettings raycast;
    Stf stf = defaultStf();
    Exposure exposure;
    TemporalCompositor compositor;  // the table's first, temporal-mip
    CompositorOptions compositorOptions;
    RayMode rayMode;  // the table's first, composite
    RayModeOptions rayOptions;
    IndexTstf indexTstf = defaultIndexTstf();
    GradientTstf gradientTstf = defaultGradientTstf();
    FinalMode finalMode = FinalMode::Modulate;
    Annotations annotations;
    Animation animation;
    // Places pinned in the window's probe panel, in the file's own coordinates (as `tstyles info`
    // lists them and `probe --at` takes them): the window plots their values over time and marks
    // them on the picture; `render` draws nothing for them (docs/probe.md).
    std::vector<glm::dvec3> probes;
    bool operator==(const Scene&) const = default;
};

// What is wrong with the scene's ray mode beside its compositor, as "KEY: problem" (a maximum of a
// compositor that has no value, an iso-value below 0 for one that shows densities); none where
// they go together.
struct RayModeProblem {
    std::string key;  // "ray.mode", "ray.values[1]"
    std::string problem;
};
std::optional<RayModeProblem> rayModeProblem(const Scene& scene);

// Fails, with an InputError naming the key of `sceneFile`, where a setting of the scene names a
// time-step that a series of `stepCount` lacks: the exposure, a time-step option of its compositor.
void checkTimeStepsFit(const Scene& scene, std::size_t stepCount, const std::filesystem::path& sceneFile);

}  // namespace tstyles
