// Scene files out: every key written explicitly, in the documented order, so that a saved scene
// is also a complete record of what was rendered (format: docs/scene-format.md).
#include <algorithm>

#include <nlohmann/json.hpp>

#include "scene_sections.h"
#include "tstyles/core/atomic_file.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/style_reference.h"

namespace tstyles {
namespace {

using nlohmann::ordered_json;

// Scalars, and arrays or objects of nothing deeper than arrays of scalars: short enough for one line.
bool fitsOnOneLine(const ordered_json& value) {
    const auto isScalar = [](const ordered_json& v) { return v.is_primitive(); };
    const auto isScalarArray = [&](const ordered_json& v) {
        return v.is_array() && std::all_of(v.begin(), v.end(), isScalar);
    };
    if (isScalar(value) || isScalarArray(value)) return true;
    return value.is_object() && std::all_of(value.begin(), value.end(), [&](const ordered_json& v) {
               return isScalar(v) || isScalarArray(v);
           });
}

std::string oneLine(const ordered_json& value) {
    if (value.is_primitive()) return value.dump();  // doubles come out in their shortest exact form
    std::string text = value.is_array() ? "[" : "{";
    bool first = true;
    for (auto member = value.begin(); member != value.end(); ++member) {
        text += first ? "" : ", ";
        if (value.is_object()) text += ordered_json(member.key()).dump() + ": ";
        text += oneLine(*member);
        first = false;
    }
    return text + (value.is_array() ? "]" : "}");
}

// Two-space indentation, but a node, a vector or a small object stays on one line: a saved scene
// is meant to be read and edited by hand, and "color": [1.0, 0.5, 0.0] spread over five lines is not.
std::string layOut(const ordered_json& value, int depth) {
    if (fitsOnOneLine(value) || value.empty()) return oneLine(value);
    const std::string inner(2 * std::size_t(depth + 1), ' ');
    std::string text = value.is_array() ? "[\n" : "{\n";
    bool first = true;
    for (auto member = value.begin(); member != value.end(); ++member) {
        text += (first ? "" : ",\n") + inner;
        if (value.is_object()) text += ordered_json(member.key()).dump() + ": ";
        text += layOut(*member, depth + 1);
        first = false;
    }
    return text + "\n" + std::string(2 * std::size_t(depth), ' ') + (value.is_array() ? "]" : "}");
}

ordered_json vectorJson(const glm::dvec3& v) { return ordered_json::array({v.x, v.y, v.z}); }

// Relative to the scene's folder when the two share a root, so that a folder of scenes and data can
// be moved as a whole; otherwise absolute. Forward slashes on every platform.
std::string pathJson(const std::filesystem::path& path, const std::filesystem::path& sceneFolder) {
    const std::filesystem::path absolutePath = std::filesystem::absolute(path).lexically_normal();
    const std::filesystem::path absoluteFolder =
        (sceneFolder.empty() ? std::filesystem::current_path() : std::filesystem::absolute(sceneFolder))
            .lexically_normal();
    const std::filesystem::path relative = absolutePath.lexically_relative(absoluteFolder);
    return (relative.empty() ? absolutePath : relative).generic_string();
}

ordered_json curveJson(const TransferFunction1D& curve, const std::filesystem::path& sceneFolder) {
    ordered_json opacity = ordered_json::array();
    for (const OpacityNode& node : curve.opacity) {
        ordered_json entry;
        entry["at"] = node.at;
        entry["opacity"] = node.opacity;
        if (node.group != 0) entry["group"] = node.group;
        opacity.push_back(entry);
    }
    ordered_json color = ordered_json::array();
    for (const ColorNode& node : curve.color) {
        ordered_json entry;
        entry["at"] = node.at;
        if (!node.style.empty()) entry["style"] = isStyleFile(node.style) ? pathJson(node.style, sceneFolder) : node.style;
        entry["color"] = vectorJson(node.color);
        if (node.group != 0) entry["group"] = node.group;
        color.push_back(entry);
    }
    ordered_json result;
    result["opacity"] = opacity;
    result["color"] = color;
    return result;
}

ordered_json orbitJson(const OrbitCamera& orbit) {
    ordered_json result;
    // An absent target or distance means "fit the series": omitting them keeps it automatic.
    if (orbit.target) result["target"] = vectorJson(*orbit.target);
    if (orbit.distance) result["distance"] = *orbit.distance;
    result["azimuth_deg"] = orbit.azimuthDeg;
    result["elevation_deg"] = orbit.elevationDeg;
    return result;
}

ordered_json lookAtJson(const LookAtCamera& lookAt) {
    ordered_json result;
    result["eye"] = vectorJson(lookAt.eye);
    result["target"] = vectorJson(lookAt.target);
    result["up"] = vectorJson(lookAt.up);
    return result;
}

ordered_json cameraJson(const Camera& camera) {
    ordered_json result;
    if (const auto* orbit = std::get_if<OrbitCamera>(&camera.pose)) {
        result["orbit"] = orbitJson(*orbit);
    } else {
        result["look_at"] = lookAtJson(std::get<LookAtCamera>(camera.pose));
    }
    if (camera.framing != Framing::Series) result["frame"] = toString(camera.framing);
    result["fov_deg"] = camera.fovDeg;
    result["projection"] = toString(camera.projection);
    return result;
}


}  // namespace

std::string sceneToJson(const Scene& scene, const std::filesystem::path& sceneFolder) {
    ordered_json root;
    root["dataset"] = pathJson(scene.dataset, sceneFolder);
    if (scene.display != DisplaySettings{}) {
        const Orientation& orientation = scene.display.orientation;
        if (orientation.mode == Orientation::Mode::Auto) root["orientation"] = "auto";
        if (orientation.mode == Orientation::Mode::Axes) {
            root["orientation"] = ordered_json::array();
            for (const SignedAxis& axis : orientation.axes) root["orientation"].push_back(toString(axis));
        }
        const Aspect& aspect = scene.display.aspect;
        root["aspect"] = aspect.mode == Aspect::Mode::Scale ? vectorJson(aspect.scale)
                         : aspect.mode == Aspect::Mode::Cubic ? ordered_json("cubic")
                         : aspect.mode == Aspect::Mode::Auto  ? ordered_json("auto")
                                                              : ordered_json("physical");
        root["vertical_exaggeration"] = scene.display.verticalExaggeration
                                            ? ordered_json(*scene.display.verticalExaggeration)
                                            : ordered_json("auto");
    }

    ordered_json& image = root["image"];
    image["width"] = scene.width;
    image["height"] = scene.height;
    const glm::dvec4& background = scene.background;
    image["background"] = ordered_json::array({background.r, background.g, background.b, background.a});

    root["camera"] = cameraJson(scene.camera);

    ordered_json& raycast = root["raycast"];
    if (scene.raycast.step) raycast["step"] = *scene.raycast.step;  // absent: half the finest spacing
    raycast["termination"] = scene.raycast.termination;

    root["stf"] = curveJson(scene.stf.curve, sceneFolder);
    root["compositor"] = compositorJson(scene, sceneFolder);
    if (const auto ray = rayJson(scene)) root["ray"] = *ray;

    ordered_json& tstf = root["tstf"];
    tstf["index"] = curveJson(scene.indexTstf.curve, sceneFolder);
    ordered_json gradient;
    gradient["range"] = scene.gradientTstf.automaticRange
                            ? ordered_json("auto")
                            : ordered_json::array({scene.gradientTstf.rangeLow, scene.gradientTstf.rangeHigh});
    gradient.update(curveJson(scene.gradientTstf.curve, sceneFolder));
    tstf["gradient"] = gradient;

    root["final"] = toString(scene.finalMode);
    if (scene.exposure != Exposure{}) {
        ordered_json& exposure = root["exposure"];
        exposure["first"] = scene.exposure.first;
        if (scene.exposure.last) exposure["last"] = *scene.exposure.last;
    }
    if (scene.annotations != Annotations{}) root["annotations"] = annotationsJson(scene.annotations);
    if (!scene.animation.empty()) root["animation"] = animationJson(scene.animation);
    if (!scene.probes.empty()) {
        ordered_json& probes = root["probes"] = ordered_json::array();
        for (const glm::dvec3& place : scene.probes) probes.push_back({place.x, place.y, place.z});
    }
    return layOut(root, 0) + "\n";
}

void saveScene(const Scene& scene, const std::filesystem::path& sceneFile) {
    requireOutputFile(PathSource{}, sceneFile, "scene file");
    const std::filesystem::path folder =
        sceneFile.has_parent_path() ? sceneFile.parent_path() : std::filesystem::current_path();
    writeFileAtomically(sceneFile, sceneToJson(scene, folder));
}

}  // namespace tstyles
