// The scene file's "compositor": a name ("temporal-mip"), or an object with a name and the
// compositor's options ({"name": "first-arrival", "threshold": 0.4}), or the scene's own GLSL
// ({"glsl": "...", "reads": "index-tstf"} or {"file": "peak.glsl", "reads": "gradient-tstf"}). A
// compositor that picks a time-step may leave unchanged places without time colour:
// {"name": "temporal-mip", "unchanged": {"below": "auto", "opacity": 0.2}}.
#include <cmath>
#include <fstream>
#include <sstream>

#include "custom_compositor_check.h"
#include "scene_sections.h"
#include "tstyles/scene/scene_keys.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

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
UnchangedTime readUnchanged(const JsonField& section) {
    section.allowOnlyKeys({"below", "tie", "gain", "boundary", "opacity"});
    UnchangedTime unchanged;
    if (const auto below = section.optionalMember("below")) {
        if (below->isString()) {
            if (below->string() != "auto")
                below->fail("expected \"auto\" or a change in [0, 1], got \"" + below->string() + "\"");
        } else {
            unchanged.automatic = false;
            unchanged.below = readKeyNumber(*below);
        }
    }
    // The keys that "auto" fits along with "below": numbers only beside a number for it.
    const auto readFitted = [&](std::string_view key, double& into) {
        const std::optional<JsonField> given = section.optionalMember(key);
        if (!given) return;
        if (unchanged.automatic) given->fail("is fitted with \"below\": \"auto\"; give \"below\" as a number with it");
        into = readKeyNumber(*given);
    };
    readFitted("tie", unchanged.tie);
    readFitted("gain", unchanged.gain);
    readFitted("boundary", unchanged.boundary);
    if (const auto opacity = section.optionalMember("opacity")) unchanged.opacity = readKeyNumber(*opacity);
    return unchanged;
}

std::string readCodeFile(const JsonField& name, const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) name.fail("no such file: " + file.string());
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) name.fail("cannot read " + file.string());
    return text.str();
}

CustomCompositor readCustom(const JsonField& section, const std::filesystem::path& origin) {
    CustomCompositor custom;
    const std::optional<JsonField> glsl = section.optionalMember("glsl");
    const std::optional<JsonField> file = section.optionalMember("file");
    if (glsl && file) section.fail("give \"glsl\" or \"file\", not both");
    if (glsl) {
        custom.glsl = glsl->string();
        custom.origin = origin;
    } else {
        const std::filesystem::path named = file->pathName();
        const std::filesystem::path folder =
            origin.empty() ? std::filesystem::current_path() : std::filesystem::absolute(origin).parent_path();
        custom.origin = (folder / named).lexically_normal();
        custom.ownFile = true;
        custom.glsl = readCodeFile(*file, custom.origin);
    }
    const JsonField& code = glsl ? *glsl : *file;
    if (custom.glsl.find_first_not_of(" \t\r\n") == std::string::npos) code.fail("the compositor's code is empty");
    if (const auto violation = findSandboxViolation(custom.glsl))
        code.fail((custom.ownFile ? custom.origin.string() + ":" : std::string("line ")) +
                  std::to_string(violation->line) + ": " + violation->problem);
    custom.reads = section.member("reads", "missing; \"index-tstf\" or \"gradient-tstf\"")
                       .name<CompositorReads>(readsFromString, {"index-tstf", "gradient-tstf"});
    return custom;
}

// A value of `option` from the compositor's object.
CompositorOptionValue readOption(const CompositorOption& option, const JsonField& field) {
    switch (option.kind) {
        case CompositorOptionKind::Number: return field.numberIn(option.range);
        case CompositorOptionKind::TimeStepPair: {
            const std::vector<double> pair = field.numbers(2, Interval{0.0, 1.0e6});
            for (std::size_t i = 0; i < 2; ++i)
                if (pair[i] != std::floor(pair[i])) field.element(i).fail("must be a whole time-step index");
            return TimeStepPair{int(pair[0]), int(pair[1])};
        }
        case CompositorOptionKind::Choice: {
            const auto choiceOf = [&](const std::string& name) { return option.choiceNamed(name); };
            return option.choices[field.name<std::size_t>(choiceOf, option.choiceNames())];
        }
    }
    field.fail("an option of an unknown kind");
}

// What the scene file holds for `option`: a number or a choice always (a default too, so that the
// file says it); time-steps only where given, since their default is the series' own.
std::optional<ordered_json> optionJson(const CompositorOption& option, const CompositorOptions& options) {
    switch (option.kind) {
        case CompositorOptionKind::Number: return ordered_json(options.number(option));
        case CompositorOptionKind::Choice: return ordered_json(option.choices[options.choice(option)]);
        case CompositorOptionKind::TimeStepPair: {
            const TimeStepPair steps = options.timeSteps(option);
            if (!steps.to) return std::nullopt;
            return ordered_json::array({steps.from, *steps.to});
        }
    }
    return std::nullopt;
}

}  // namespace

void readCompositor(const JsonField& section, const std::filesystem::path& origin, Scene& scene) {
    if (section.isString()) {
        scene.compositor = section.name<TemporalCompositor>(temporalCompositorFromString, temporalCompositorNames());
        return;
    }
    if (!section.isObject())
        section.fail("expected a name or an object, got " + std::string(section.value().type_name()));
    // Every compositor's options, so that one of another compositor is refused as not taken.
    std::vector<std::string_view> keys = {"name", "glsl", "file", "reads", "unchanged"};
    for (const CompositorOption* option : compositorOptionsOfAll()) keys.emplace_back(option->key);
    section.allowOnlyKeys(keys);
    CompositorOptions& options = scene.compositorOptions;
    if (section.optionalMember("glsl") || section.optionalMember("file")) {
        if (section.optionalMember("name")) section.failAt("name", "a compositor with its own code has no name");
        scene.compositor = kCustomCompositor;
        options.custom = readCustom(section, origin);
    } else {
        scene.compositor =
            section.member("name").name<TemporalCompositor>(temporalCompositorFromString, temporalCompositorNames());
        if (section.optionalMember("reads"))
            section.failAt("reads", "only a compositor with its own code says what reads it");
    }
    const TemporalCompositorInfo& info = compositorInfo(scene.compositor);
    for (const CompositorOption* known : compositorOptionsOfAll()) {
        const std::optional<JsonField> given = section.optionalMember(known->key);
        if (!given) continue;
        const CompositorOption* option = info.options.find(known->key);
        if (!option) given->fail(std::string(info.name) + " takes no " + known->key);
        options.values[option->key] = readOption(*option, *given);
    }
    if (const auto unchanged = section.optionalMember("unchanged")) {
        if (!info.takesUnchanged)
            unchanged->fail(std::string(info.name) + " does not pick a time-step, so no place is left without time "
                            "colour (" + listedNames(compositorsTakingUnchanged()) + " do)");
        options.unchanged = readUnchanged(*unchanged);
    }
}

ordered_json compositorJson(const Scene& scene, const std::filesystem::path& sceneFolder) {
    const TemporalCompositorInfo& info = compositorInfo(scene.compositor);
    const CompositorOptions& options = scene.compositorOptions;
    if (scene.compositor == kCustomCompositor && options.custom) {
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
    if (info.options.empty() && !unchanged) return info.name;
    ordered_json object;
    object["name"] = info.name;
    for (const CompositorOption& option : info.options)
        if (const std::optional<ordered_json> value = optionJson(option, options)) object[option.key] = *value;
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
