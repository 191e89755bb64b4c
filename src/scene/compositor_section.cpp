// The scene file's "compositor": a name ("temporal-mip"), or an object with a name and the
// compositor's options ({"name": "first-arrival", "threshold": 0.4}), or the scene's own GLSL
// ({"glsl": "...", "reads": "index-tstf"} or {"file": "peak.glsl", "reads": "gradient-tstf"}). A
// compositor that picks a time-step may leave unchanged places without time colour:
// {"name": "temporal-mip", "unchanged": {"below": "auto", "opacity": 0.2}}.
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "custom_compositor_check.h"
#include "scene_sections.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr std::pair<CompositorReads, const char*> kReadsNames[] = {
    {CompositorReads::IndexTstf, "index-tstf"},
    {CompositorReads::GradientTstf, "gradient-tstf"},
};

std::optional<CompositorReads> readsFromString(const std::string& name) {
    for (const auto& [reads, text] : kReadsNames)
        if (name == text) return reads;
    return std::nullopt;
}

std::string readsName(CompositorReads reads) {
    for (const auto& [entry, text] : kReadsNames)
        if (entry == reads) return text;
    return "index-tstf";
}

// {"below": "auto" or a change in density units, "tie": a difference in density units and "gain"
// (with a number for "below"), "opacity": the share of the STF's opacity kept}, all optional.
UnchangedTime readUnchanged(const JsonFieldReader& fields, const json& value) {
    const std::string path = "compositor.unchanged";
    fields.expectObject(value, path, {"below", "tie", "gain", "boundary", "opacity"});
    UnchangedTime unchanged;
    if (const json* below = JsonFieldReader::member(value, "below")) {
        if (below->is_string()) {
            if (below->get<std::string>() != "auto")
                fields.fail(path + ".below", "expected \"auto\" or a change in [0, 1], got \"" +
                                                 below->get<std::string>() + "\"");
        } else {
            unchanged.automatic = false;
            unchanged.below = fields.numberIn(*below, path + ".below", Interval{0.0, 1.0});
        }
    }
    // The keys that "auto" fits along with "below": numbers only beside a number for it.
    const auto readFitted = [&](std::string_view key, const Interval& allowed, double& into) {
        const json* given = JsonFieldReader::member(value, key);
        if (!given) return;
        const std::string keyPath = childPath(path, key);
        if (unchanged.automatic)
            fields.fail(keyPath, "is fitted with \"below\": \"auto\"; give \"below\" as a number with it");
        into = fields.numberIn(*given, keyPath, allowed);
    };
    readFitted("tie", Interval{0.0, 1.0}, unchanged.tie);
    readFitted("gain", Interval{1.0, 8.0}, unchanged.gain);
    readFitted("boundary", Interval{0.0, std::numeric_limits<double>::max()}, unchanged.boundary);
    if (const json* opacity = JsonFieldReader::member(value, "opacity"))
        unchanged.opacity = fields.numberIn(*opacity, path + ".opacity", Interval{0.0, 1.0});
    return unchanged;
}

std::string readCodeFile(const JsonFieldReader& fields, const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))
        fields.fail("compositor.file", "no such file: " + file.string());
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) fields.fail("compositor.file", "cannot read " + file.string());
    return text.str();
}

CustomCompositor readCustom(const JsonFieldReader& fields, const json& value, const std::filesystem::path& origin) {
    CustomCompositor custom;
    const json* glsl = JsonFieldReader::member(value, "glsl");
    const json* file = JsonFieldReader::member(value, "file");
    if (glsl && file) fields.fail("compositor", "give \"glsl\" or \"file\", not both");
    if (glsl) {
        custom.glsl = fields.string(*glsl, "compositor.glsl");
        custom.origin = origin;
    } else {
        const std::filesystem::path named = fields.pathName(*file, "compositor.file");
        const std::filesystem::path folder =
            origin.empty() ? std::filesystem::current_path() : std::filesystem::absolute(origin).parent_path();
        custom.origin = (folder / named).lexically_normal();
        custom.ownFile = true;
        custom.glsl = readCodeFile(fields, custom.origin);
    }
    const std::string codeField = glsl ? "compositor.glsl" : "compositor.file";
    if (custom.glsl.find_first_not_of(" \t\r\n") == std::string::npos) fields.fail(codeField, "the compositor's code is empty");
    if (const auto violation = findSandboxViolation(custom.glsl))
        fields.fail(codeField, (custom.ownFile ? custom.origin.string() + ":" : std::string("line ")) +
                                   std::to_string(violation->line) + ": " + violation->problem);
    const json* reads = JsonFieldReader::member(value, "reads");
    if (!reads) fields.fail("compositor.reads", "missing; \"index-tstf\" or \"gradient-tstf\"");
    custom.reads = fields.name<CompositorReads>(*reads, "compositor.reads", readsFromString,
                                                {"index-tstf", "gradient-tstf"});
    return custom;
}

}  // namespace

void readCompositor(const JsonFieldReader& fields, const json& value, const std::filesystem::path& origin,
                    Scene& scene) {
    if (value.is_string()) {
        scene.compositor = fields.name<TemporalCompositor>(value, "compositor", temporalCompositorFromString,
                                                           temporalCompositorNames());
        return;
    }
    if (!value.is_object())
        fields.fail("compositor", "expected a name or an object, got " + std::string(value.type_name()));
    fields.expectObject(value, "compositor", {"name", "threshold", "steps", "glsl", "file", "reads", "unchanged"});
    CompositorOptions& options = scene.compositorOptions;
    if (JsonFieldReader::member(value, "glsl") || JsonFieldReader::member(value, "file")) {
        if (JsonFieldReader::member(value, "name"))
            fields.fail("compositor.name", "a compositor with its own code has no name");
        scene.compositor = TemporalCompositor::Custom;
        options.custom = readCustom(fields, value, origin);
    } else {
        const json& name = fields.requiredMember(value, "compositor", "name");
        scene.compositor = fields.name<TemporalCompositor>(name, "compositor.name", temporalCompositorFromString,
                                                           temporalCompositorNames());
        if (JsonFieldReader::member(value, "reads"))
            fields.fail("compositor.reads", "only a compositor with its own code says what reads it");
    }
    const TemporalCompositorInfo& info = compositorInfo(scene.compositor);
    if (const json* threshold = JsonFieldReader::member(value, "threshold")) {
        if (!info.takesThreshold) fields.fail("compositor.threshold", std::string(info.name) + " takes no threshold");
        options.threshold = fields.numberIn(*threshold, "compositor.threshold", Interval{0.0, 1.0});
    }
    if (const json* steps = JsonFieldReader::member(value, "steps")) {
        if (!info.takesSteps) fields.fail("compositor.steps", std::string(info.name) + " takes no steps");
        const std::vector<double> pair = fields.numbers(*steps, "compositor.steps", 2, Interval{0.0, 1.0e6});
        for (int i = 0; i < 2; ++i)
            if (pair[std::size_t(i)] != std::floor(pair[std::size_t(i)]))
                fields.fail("compositor.steps[" + std::to_string(i) + "]", "must be a whole time-step index");
        options.differenceFrom = int(pair[0]);
        options.differenceTo = int(pair[1]);
    }
    if (const json* unchanged = JsonFieldReader::member(value, "unchanged")) {
        if (!info.takesUnchanged)
            fields.fail("compositor.unchanged", std::string(info.name) +
                                                    " does not pick a time-step, so no place is left without time "
                                                    "colour (temporal-mip, temporal-min, time-of-max, first-arrival "
                                                    "and last-above do)");
        options.unchanged = readUnchanged(fields, *unchanged);
    }
}

ordered_json compositorJson(const Scene& scene, const std::filesystem::path& sceneFolder) {
    const TemporalCompositorInfo& info = compositorInfo(scene.compositor);
    const CompositorOptions& options = scene.compositorOptions;
    if (scene.compositor == TemporalCompositor::Custom && options.custom) {
        ordered_json custom;
        // Code read from a file of its own stays in that file; inline code stays inline.
        if (!options.custom->ownFile)
            custom["glsl"] = options.custom->glsl;
        else
            custom["file"] = sceneFolder.empty() ? options.custom->origin.string()
                                                 : options.custom->origin.lexically_proximate(sceneFolder).string();
        custom["reads"] = readsName(options.custom->reads);
        return custom;
    }
    const bool unchanged = info.takesUnchanged && options.unchanged;
    if (!info.takesThreshold && !info.takesSteps && !unchanged) return info.name;
    ordered_json object;
    object["name"] = info.name;
    if (info.takesThreshold) object["threshold"] = options.threshold;
    // No `to`: from the first time-step to the last, the default.
    if (info.takesSteps && options.differenceTo)
        object["steps"] = ordered_json::array({options.differenceFrom, *options.differenceTo});
    if (unchanged) {
        ordered_json section;
        section["below"] = options.unchanged->automatic ? ordered_json("auto") : ordered_json(options.unchanged->below);
        if (!options.unchanged->automatic) {
            section["tie"] = options.unchanged->tie;
            section["gain"] = options.unchanged->gain;
            section["boundary"] = options.unchanged->boundary;
        }
        section["opacity"] = options.unchanged->opacity;
        object["unchanged"] = section;
    }
    return object;
}

}  // namespace tstyles
