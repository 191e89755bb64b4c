// Scene files in: JSON text to a validated Scene (format: docs/scene-format.md). Every key that is
// absent keeps the default of a default-constructed Scene, so the defaults live in one place.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "json_fields.h"
#include "scene_sections.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/json_text.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/style_reference.h"

namespace tstyles {
namespace {

using nlohmann::json;

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr Interval unitInterval{0.0, 1.0};
constexpr Interval positive{0.0, infinity, false};

// Editor groups are numbered from 1; a node without "group" belongs to none.
NodeGroup readGroup(const JsonFieldReader& fields, const json& node, const std::string& nodePath) {
    const json* group = JsonFieldReader::member(node, "group");
    return group ? fields.integerIn(*group, childPath(nodePath, "group"), 1, 1000000) : 0;
}

// Positions along a curve's axis: density or normalized change in [0, 1], or time-step units.
void readOpacityNodes(const JsonFieldReader& fields, const json& value, const std::string& path,
                      const Interval& positions, std::vector<OpacityNode>& nodes) {
    fields.expectArray(value, path);
    nodes.clear();
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string nodePath = elementPath(path, i);
        fields.expectObject(value[i], nodePath, {"at", "opacity", "group"});
        OpacityNode node;
        node.at = fields.numberIn(fields.requiredMember(value[i], nodePath, "at"), childPath(nodePath, "at"),
                                  positions);
        node.opacity = fields.numberIn(fields.requiredMember(value[i], nodePath, "opacity"),
                                       childPath(nodePath, "opacity"), unitInterval);
        node.group = readGroup(fields, value[i], nodePath);
        nodes.push_back(node);
    }
}

void readColorNodes(const JsonFieldReader& fields, const json& value, const std::string& path,
                    const Interval& positions, std::vector<ColorNode>& nodes) {
    fields.expectArray(value, path);
    nodes.clear();
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string nodePath = elementPath(path, i);
        fields.expectObject(value[i], nodePath, {"at", "color", "style", "group"});
        ColorNode node;
        node.at = fields.numberIn(fields.requiredMember(value[i], nodePath, "at"), childPath(nodePath, "at"),
                                  positions);
        if (const json* style = JsonFieldReader::member(value[i], "style")) {
            node.style = fields.pathName(*style, childPath(nodePath, "style"));
            if (node.style.empty()) fields.fail(childPath(nodePath, "style"), "must name a style, got \"\"");
        }
        // A style node's colour tints the style and may be left out; a flat node needs one.
        if (const json* color = JsonFieldReader::member(value[i], "color"))
            node.color = fields.vec3(*color, childPath(nodePath, "color"), unitInterval);
        else if (node.style.empty())
            fields.requiredMember(value[i], nodePath, "color");
        node.group = readGroup(fields, value[i], nodePath);
        nodes.push_back(node);
    }
}

// The "opacity" and "color" lists of an object whose keys the caller has already checked.
void readCurve(const JsonFieldReader& fields, const json& object, const std::string& path,
               const Interval& positions, TransferFunction1D& curve) {
    if (const json* opacity = JsonFieldReader::member(object, "opacity")) {
        readOpacityNodes(fields, *opacity, childPath(path, "opacity"), positions, curve.opacity);
    }
    if (const json* color = JsonFieldReader::member(object, "color")) {
        readColorNodes(fields, *color, childPath(path, "color"), positions, curve.color);
    }
    curve.sortNodes();
}

void readGradientRange(const JsonFieldReader& fields, const json& value, const std::string& path,
                       GradientTstf& tstf) {
    if (!value.is_array()) fields.fail(path, "expected [low, high] or \"auto\", got " + std::string(value.type_name()));
    // Signed characteristics (a trend, a difference) take a range around 0.
    const std::vector<double> range = fields.numbers(value, path, 2, Interval{-infinity, infinity});
    if (!(range[0] < range[1])) {
        fields.fail(path, "must be [low, high] with low < high, got [" + formatNumber(range[0]) + ", " +
                              formatNumber(range[1]) + "]");
    }
    tstf.rangeLow = range[0];
    tstf.rangeHigh = range[1];
}

void readTstf(const JsonFieldReader& fields, const json& value, Scene& scene) {
    const std::string path = "tstf";
    fields.expectObject(value, path, {"index", "gradient"});
    if (const json* index = JsonFieldReader::member(value, "index")) {
        const std::string indexPath = childPath(path, "index");
        fields.expectObject(*index, indexPath, {"opacity", "color"});
        readCurve(fields, *index, indexPath, anyFinite, scene.indexTstf.curve);
    }
    if (const json* gradient = JsonFieldReader::member(value, "gradient")) {
        const std::string gradientPath = childPath(path, "gradient");
        fields.expectObject(*gradient, gradientPath, {"range", "opacity", "color"});
        if (const json* range = JsonFieldReader::member(*gradient, "range")) {
            if (range->is_string() && range->get<std::string>() == "auto")
                scene.gradientTstf.automaticRange = true;
            else
                readGradientRange(fields, *range, childPath(gradientPath, "range"), scene.gradientTstf);
        }
        readCurve(fields, *gradient, gradientPath, unitInterval, scene.gradientTstf.curve);
    }
}

void readImage(const JsonFieldReader& fields, const json& value, Scene& scene) {
    const std::string path = "image";
    fields.expectObject(value, path, {"width", "height", "background"});
    constexpr int largestSide = 16384;
    if (const json* width = JsonFieldReader::member(value, "width")) {
        scene.width = fields.integerIn(*width, childPath(path, "width"), 1, largestSide);
    }
    if (const json* height = JsonFieldReader::member(value, "height")) {
        scene.height = fields.integerIn(*height, childPath(path, "height"), 1, largestSide);
    }
    if (const json* background = JsonFieldReader::member(value, "background")) {
        const std::vector<double> rgba =
            fields.numbers(*background, childPath(path, "background"), 4, unitInterval);
        scene.background = {rgba[0], rgba[1], rgba[2], rgba[3]};
    }
}

void readRaycast(const JsonFieldReader& fields, const json& value, Scene& scene) {
    const std::string path = "raycast";
    fields.expectObject(value, path, {"step", "termination"});
    if (const json* step = JsonFieldReader::member(value, "step")) {
        scene.raycast.step = fields.numberIn(*step, childPath(path, "step"), positive);
    }
    if (const json* termination = JsonFieldReader::member(value, "termination")) {
        scene.raycast.termination =
            fields.numberIn(*termination, childPath(path, "termination"), {0.0, 1.0, false, true});
    }
}

// "exposure": {"first": 2, "last": 5}; whether they fit the series is checked when the two meet.
void readExposure(const JsonFieldReader& fields, const json& value, Exposure& exposure) {
    const std::string path = "exposure";
    fields.expectObject(value, path, {"first", "last"});
    constexpr int largestStep = 1000000;
    if (const json* first = JsonFieldReader::member(value, "first"))
        exposure.first = fields.integerIn(*first, childPath(path, "first"), 0, largestStep);
    if (const json* last = JsonFieldReader::member(value, "last"))
        exposure.last = fields.integerIn(*last, childPath(path, "last"), 0, largestStep);
    if (exposure.last && *exposure.last < exposure.first)
        fields.fail(childPath(path, "last"), "is " + std::to_string(*exposure.last) + ", before exposure.first (" +
                                                 std::to_string(exposure.first) + ")");
}

void readStf(const JsonFieldReader& fields, const json& value, Scene& scene) {
    fields.expectObject(value, "stf", {"opacity", "color"});
    readCurve(fields, value, "stf", unitInterval, scene.stf.curve);
}

OrbitCamera readOrbit(const JsonFieldReader& fields, const json& value, const std::string& path) {
    fields.expectObject(value, path, {"target", "distance", "azimuth_deg", "elevation_deg"});
    OrbitCamera orbit;
    if (const json* target = JsonFieldReader::member(value, "target")) {
        orbit.target = fields.vec3(*target, childPath(path, "target"), anyFinite);
    }
    if (const json* distance = JsonFieldReader::member(value, "distance")) {
        orbit.distance = fields.numberIn(*distance, childPath(path, "distance"), positive);
    }
    if (const json* azimuth = JsonFieldReader::member(value, "azimuth_deg")) {
        orbit.azimuthDeg = fields.finiteNumber(*azimuth, childPath(path, "azimuth_deg"));
    }
    if (const json* elevation = JsonFieldReader::member(value, "elevation_deg")) {
        orbit.elevationDeg = fields.numberIn(*elevation, childPath(path, "elevation_deg"), {-90.0, 90.0});
    }
    return orbit;
}

// Eye and target are required: the LookAtCamera defaults only make sense for data near the origin.
LookAtCamera readLookAt(const JsonFieldReader& fields, const json& value, const std::string& path) {
    fields.expectObject(value, path, {"eye", "target", "up"});
    LookAtCamera lookAt;
    lookAt.eye = fields.vec3(fields.requiredMember(value, path, "eye"), childPath(path, "eye"), anyFinite);
    lookAt.target =
        fields.vec3(fields.requiredMember(value, path, "target"), childPath(path, "target"), anyFinite);
    if (const json* up = JsonFieldReader::member(value, "up")) {
        lookAt.up = fields.vec3(*up, childPath(path, "up"), anyFinite);
    }

    const glm::dvec3 viewDirection = lookAt.target - lookAt.eye;
    if (glm::length(viewDirection) == 0.0) fields.fail(childPath(path, "target"), "must differ from eye");
    if (glm::length(lookAt.up) == 0.0) fields.fail(childPath(path, "up"), "must not be the zero vector");
    // Relative test, so that the scale of the coordinates does not matter.
    const double sine = glm::length(glm::cross(glm::normalize(viewDirection), glm::normalize(lookAt.up)));
    if (sine < 1e-6) {
        fields.fail(childPath(path, "up"), "must not be parallel to the view direction (target - eye)");
    }
    return lookAt;
}

void readCamera(const JsonFieldReader& fields, const json& value, Camera& camera) {
    const std::string path = "camera";
    fields.expectObject(value, path, {"orbit", "look_at", "frame", "fov_deg", "projection"});
    const json* orbit = JsonFieldReader::member(value, "orbit");
    const json* lookAt = JsonFieldReader::member(value, "look_at");
    if (orbit && lookAt) fields.fail(path, "has both orbit and look_at; give exactly one");
    if (orbit) camera.pose = readOrbit(fields, *orbit, childPath(path, "orbit"));
    if (lookAt) camera.pose = readLookAt(fields, *lookAt, childPath(path, "look_at"));
    if (const json* frame = JsonFieldReader::member(value, "frame")) {
        camera.framing = fields.name<Framing>(*frame, childPath(path, "frame"), framingFromString, framingNames());
    }
    if (const json* fov = JsonFieldReader::member(value, "fov_deg")) {
        camera.fovDeg = fields.numberIn(*fov, childPath(path, "fov_deg"), {0.0, 180.0, false, false});
    }
    if (const json* projection = JsonFieldReader::member(value, "projection")) {
        camera.projection = fields.name<Projection>(*projection, childPath(path, "projection"),
                                                    projectionFromString, projectionNames());
    }
}

// "orientation": "data", "auto" or three signed axes ["+x", "+z", "-y"] that make a rotation.
Orientation readOrientation(const JsonFieldReader& fields, const json& value) {
    const std::string path = "orientation";
    Orientation orientation;
    if (value.is_string()) {
        const std::string mode = value.get<std::string>();
        if (mode == "data") return orientation;
        if (mode == "auto") {
            orientation.mode = Orientation::Mode::Auto;
            return orientation;
        }
        fields.fail(path, "unknown value \"" + mode + "\"; allowed: \"data\", \"auto\" or three axes such as "
                          "[\"+x\", \"+z\", \"-y\"]");
    }
    fields.expectArray(value, path);
    if (value.size() != 3) fields.fail(path, "expected three axes (display x, y, z), got " + std::to_string(value.size()));
    orientation.mode = Orientation::Mode::Axes;
    std::array<bool, 3> used{};
    for (std::size_t i = 0; i < 3; ++i) {
        const std::string text = fields.string(value[i], elementPath(path, i));
        const auto axis = signedAxisFromString(text);
        if (!axis) fields.fail(elementPath(path, i), "expected +x, -x, +y, -y, +z or -z, got \"" + text + "\"");
        if (used[std::size_t(axis->axis)]) fields.fail(path, "names an axis twice");
        used[std::size_t(axis->axis)] = true;
        orientation.axes[i] = *axis;
    }
    if (glm::determinant(rotationOf(orientation.axes)) < 0.0)
        fields.fail(path, "mirrors the data (a left-handed frame); negate one axis");
    return orientation;
}

// "aspect": "physical", "cubic", "auto" or a scale per display axis [sx, sy, sz].
Aspect readAspect(const JsonFieldReader& fields, const json& value) {
    Aspect aspect;
    if (value.is_string()) {
        const std::string mode = value.get<std::string>();
        if (mode == "physical") return aspect;
        aspect.mode = mode == "cubic" ? Aspect::Mode::Cubic : mode == "auto" ? Aspect::Mode::Auto : Aspect::Mode::Scale;
        if (aspect.mode == Aspect::Mode::Scale)
            fields.fail("aspect", "unknown value \"" + mode + "\"; allowed: \"physical\", \"cubic\", \"auto\" or "
                                  "a scale per axis [sx, sy, sz]");
        return aspect;
    }
    aspect.mode = Aspect::Mode::Scale;
    aspect.scale = fields.vec3(value, "aspect", positive);
    return aspect;
}

void readDisplay(const JsonFieldReader& fields, const json& root, DisplaySettings& display) {
    if (const json* orientation = JsonFieldReader::member(root, "orientation"))
        display.orientation = readOrientation(fields, *orientation);
    if (const json* aspect = JsonFieldReader::member(root, "aspect")) display.aspect = readAspect(fields, *aspect);
    if (const json* exaggeration = JsonFieldReader::member(root, "vertical_exaggeration")) {
        if (exaggeration->is_string() && exaggeration->get<std::string>() == "auto")
            display.verticalExaggeration.reset();
        else if (exaggeration->is_string())
            fields.fail("vertical_exaggeration", "expected a number > 0 or \"auto\", got \"" +
                                                     exaggeration->get<std::string>() + "\"");
        else
            display.verticalExaggeration = fields.numberIn(*exaggeration, "vertical_exaggeration", positive);
    }
}

// The dataset need not exist yet: the dataset loader reports a missing one, naming the manifest.
std::filesystem::path readDataset(const JsonFieldReader& fields, const json& root,
                                  const std::filesystem::path& origin) {
    const json* dataset = JsonFieldReader::member(root, "dataset");
    if (!dataset) fields.fail("dataset", "missing; a scene must name its dataset (a series manifest)");
    const std::filesystem::path datasetPath = fields.pathName(*dataset, "dataset");
    if (datasetPath.empty()) fields.fail("dataset", "must not be empty");
    // Relative to the scene file's folder; text read from no file is relative to the current directory.
    const std::filesystem::path sceneFolder =
        origin.empty() ? std::filesystem::current_path() : std::filesystem::absolute(origin).parent_path();
    return (sceneFolder / datasetPath).lexically_normal();
}

// Style images named by a relative path are relative to the scene file's folder, like the dataset.
void resolveStyleFiles(Scene& scene, const std::filesystem::path& origin) {
    const std::filesystem::path sceneFolder =
        origin.empty() ? std::filesystem::current_path() : std::filesystem::absolute(origin).parent_path();
    for (TransferFunction1D* curve : {&scene.stf.curve, &scene.indexTstf.curve, &scene.gradientTstf.curve})
        for (ColorNode& node : curve->color)
            if (isStyleFile(node.style) && std::filesystem::path(node.style).is_relative())
                node.style = (sceneFolder / node.style).lexically_normal().string();
}

}  // namespace

Scene parseScene(const std::string& text, const std::filesystem::path& origin) {
    const JsonFieldReader fields(origin);
    // Comments are allowed so that hand-written scenes can explain themselves.
    const json root = parseJsonText(text, origin, JsonComments::Allowed);
    fields.expectObject(root, "",
                        {"dataset", "image", "camera", "raycast", "stf", "compositor", "tstf", "final", "orientation",
                         "aspect", "vertical_exaggeration", "exposure", "annotations", "animation"});

    Scene scene;
    scene.dataset = readDataset(fields, root, origin);
    readDisplay(fields, root, scene.display);
    if (const json* image = JsonFieldReader::member(root, "image")) readImage(fields, *image, scene);
    if (const json* camera = JsonFieldReader::member(root, "camera"))
        readCamera(fields, *camera, scene.camera);
    if (const json* raycast = JsonFieldReader::member(root, "raycast")) readRaycast(fields, *raycast, scene);
    if (const json* stf = JsonFieldReader::member(root, "stf")) readStf(fields, *stf, scene);
    if (const json* compositor = JsonFieldReader::member(root, "compositor"))
        readCompositor(fields, *compositor, origin, scene);
    if (const json* tstf = JsonFieldReader::member(root, "tstf")) readTstf(fields, *tstf, scene);
    if (const json* exposure = JsonFieldReader::member(root, "exposure")) readExposure(fields, *exposure, scene.exposure);
    if (const json* finalMode = JsonFieldReader::member(root, "final")) {
        scene.finalMode = fields.name<FinalMode>(*finalMode, "final", finalModeFromString, finalModeNames());
    }
    if (const json* annotations = JsonFieldReader::member(root, "annotations"))
        scene.annotations = readAnnotations(fields, *annotations);
    resolveStyleFiles(scene, origin);
    // Last: its keys are checked against the scene read so far.
    if (const json* animation = JsonFieldReader::member(root, "animation"))
        scene.animation = readAnimation(fields, *animation, scene, origin);
    return scene;
}

Scene loadScene(const std::filesystem::path& sceneFile) {
    // A folder opens as a stream on some systems and then reads as empty: say what it is instead.
    // A missing file is left to the stream below, whose message says why it cannot be opened.
    if (userPathKind({}, sceneFile) != PathKind::Missing) requireUserFile({}, sceneFile, "scene file");
    std::ifstream in(sceneFile, std::ios::binary);
    if (!in)
        throwInputError(sceneFile, "", std::string("cannot open the scene file: ") + std::strerror(errno));
    std::stringstream text;
    text << in.rdbuf();
    if (in.bad()) throwInputError(sceneFile, "", "cannot read the scene file");
    return parseScene(text.str(), sceneFile);
}

}  // namespace tstyles
