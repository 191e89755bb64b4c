// Scene files in: JSON text to a validated Scene (format: docs/scene-format.md). Every key that is
// absent keeps the default of a default-constructed Scene, so the defaults live in one place.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "scene_sections.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/json_field.h"
#include "tstyles/core/json_text.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/scene_keys.h"
#include "tstyles/scene/style_reference.h"

namespace tstyles {
namespace {

using nlohmann::json;

// Editor groups are numbered from 1; a node without "group" belongs to none.
NodeGroup readGroup(const JsonField& node) {
    const std::optional<JsonField> group = node.optionalMember("group");
    return group ? group->integerIn(1, 1000000) : 0;
}

// Positions along a curve's axis: density or normalized change in [0, 1], or time-step units.
void readOpacityNodes(const JsonField& list, const Interval& positions, std::vector<OpacityNode>& nodes) {
    nodes.clear();
    for (std::size_t i = 0; i < list.arraySize(); ++i) {
        const JsonField entry = list.element(i);
        entry.allowOnlyKeys({"at", "opacity", "group"});
        OpacityNode node;
        node.at = entry.member("at").numberIn(positions);
        node.opacity = entry.member("opacity").numberIn(unitInterval);
        node.group = readGroup(entry);
        nodes.push_back(node);
    }
}

void readColorNodes(const JsonField& list, const Interval& positions, std::vector<ColorNode>& nodes) {
    nodes.clear();
    for (std::size_t i = 0; i < list.arraySize(); ++i) {
        const JsonField entry = list.element(i);
        entry.allowOnlyKeys({"at", "color", "style", "group"});
        ColorNode node;
        node.at = entry.member("at").numberIn(positions);
        if (const auto style = entry.optionalMember("style")) {
            node.style = style->pathName();
            if (node.style.empty()) style->fail("must name a style, got \"\"");
        }
        // A style node's colour tints the style and may be left out; a flat node needs one.
        if (const auto color = entry.optionalMember("color"))
            node.color = color->vec3(unitInterval);
        else if (node.style.empty())
            entry.member("color");
        node.group = readGroup(entry);
        nodes.push_back(node);
    }
}

// The "opacity" and "color" lists of an object whose keys the caller has already checked.
void readCurve(const JsonField& object, const Interval& positions, TransferFunction1D& curve) {
    if (const auto opacity = object.optionalMember("opacity")) readOpacityNodes(*opacity, positions, curve.opacity);
    if (const auto color = object.optionalMember("color")) readColorNodes(*color, positions, curve.color);
    curve.sortNodes();
}

void readGradientRange(const JsonField& range, GradientTstf& tstf) {
    if (!range.isArray()) range.fail("expected [low, high] or \"auto\", got " + std::string(range.value().type_name()));
    // Signed characteristics (a trend, a difference) take a range around 0.
    const std::vector<double> ends = range.numbers(2, anyFinite);
    if (!(ends[0] < ends[1]))
        range.fail("must be [low, high] with low < high, got [" + formatNumber(ends[0]) + ", " + formatNumber(ends[1]) +
                   "]");
    tstf.rangeLow = ends[0];
    tstf.rangeHigh = ends[1];
}

void readTstf(const JsonField& tstf, Scene& scene) {
    tstf.allowOnlyKeys({"index", "gradient"});
    if (const auto index = tstf.optionalMember("index")) {
        index->allowOnlyKeys({"opacity", "color"});
        readCurve(*index, anyFinite, scene.indexTstf.curve);
    }
    if (const auto gradient = tstf.optionalMember("gradient")) {
        gradient->allowOnlyKeys({"range", "opacity", "color"});
        if (const auto range = gradient->optionalMember("range")) {
            if (range->isString() && range->value().get<std::string>() == "auto")
                scene.gradientTstf.automaticRange = true;
            else
                readGradientRange(*range, scene.gradientTstf);
        }
        readCurve(*gradient, unitInterval, scene.gradientTstf.curve);
    }
}

void readImage(const JsonField& image, Scene& scene) {
    image.allowOnlyKeys({"width", "height", "background"});
    if (const auto width = image.optionalMember("width")) scene.width = int(readKeyNumber(*width));
    if (const auto height = image.optionalMember("height")) scene.height = int(readKeyNumber(*height));
    if (const auto background = image.optionalMember("background")) {
        const std::vector<double> rgba = background->numbers(4, unitInterval);
        scene.background = {rgba[0], rgba[1], rgba[2], rgba[3]};
    }
}

void readRaycast(const JsonField& raycast, Scene& scene) {
    raycast.allowOnlyKeys({"step", "termination"});
    if (const auto step = raycast.optionalMember("step")) scene.raycast.step = readKeyNumber(*step);
    if (const auto termination = raycast.optionalMember("termination"))
        scene.raycast.termination = readKeyNumber(*termination);
}

// "exposure": {"first": 2, "last": 5}; whether they fit the series is checked when the two meet.
void readExposure(const JsonField& section, Exposure& exposure) {
    section.allowOnlyKeys({"first", "last"});
    if (const auto first = section.optionalMember("first")) exposure.first = int(readKeyNumber(*first));
    if (const auto last = section.optionalMember("last")) {
        exposure.last = int(readKeyNumber(*last));
        if (const auto problem = exposure.orderProblem()) last->fail(*problem);
    }
}

// "probes": [[x, y, z], ...] in the file's coordinates; whether they meet the series is the
// window's to say (a place outside every grid plots as missing).
std::vector<glm::dvec3> readProbes(const JsonField& section) {
    if (!section.isArray()) section.fail("expected a list of places [x, y, z], got " + section.typeWithArticle());
    if (section.arraySize() > kMaxProbes)
        section.fail("at most " + std::to_string(kMaxProbes) + " places, got " + std::to_string(section.arraySize()));
    std::vector<glm::dvec3> probes;
    for (std::size_t index = 0; index < section.arraySize(); ++index) probes.push_back(section.element(index).vec3());
    return probes;
}

void readStf(const JsonField& stf, Scene& scene) {
    stf.allowOnlyKeys({"opacity", "color"});
    readCurve(stf, unitInterval, scene.stf.curve);
}

OrbitCamera readOrbit(const JsonField& section) {
    section.allowOnlyKeys({"target", "distance", "azimuth_deg", "elevation_deg"});
    OrbitCamera orbit;
    if (const auto target = section.optionalMember("target")) orbit.target = target->vec3(anyFinite);
    if (const auto distance = section.optionalMember("distance")) orbit.distance = readKeyNumber(*distance);
    if (const auto azimuth = section.optionalMember("azimuth_deg")) orbit.azimuthDeg = readKeyNumber(*azimuth);
    if (const auto elevation = section.optionalMember("elevation_deg"))
        orbit.elevationDeg = readKeyNumber(*elevation);
    return orbit;
}

// Eye and target are required: the LookAtCamera defaults only make sense for data near the origin.
LookAtCamera readLookAt(const JsonField& section) {
    section.allowOnlyKeys({"eye", "target", "up"});
    LookAtCamera lookAt;
    lookAt.eye = section.member("eye").vec3(anyFinite);
    const JsonField target = section.member("target");
    lookAt.target = target.vec3(anyFinite);
    if (const auto up = section.optionalMember("up")) lookAt.up = up->vec3(anyFinite);

    const glm::dvec3 viewDirection = lookAt.target - lookAt.eye;
    if (glm::length(viewDirection) == 0.0) target.fail("must differ from eye");
    if (glm::length(lookAt.up) == 0.0) section.failAt("up", "must not be the zero vector");
    // Relative test, so that the scale of the coordinates does not matter.
    const double sine = glm::length(glm::cross(glm::normalize(viewDirection), glm::normalize(lookAt.up)));
    if (sine < 1e-6) section.failAt("up", "must not be parallel to the view direction (target - eye)");
    return lookAt;
}

void readCamera(const JsonField& section, Camera& camera) {
    section.allowOnlyKeys({"orbit", "look_at", "frame", "fov_deg", "projection"});
    const std::optional<JsonField> orbit = section.optionalMember("orbit");
    const std::optional<JsonField> lookAt = section.optionalMember("look_at");
    if (orbit && lookAt) section.fail("has both orbit and look_at; give exactly one");
    if (orbit) camera.pose = readOrbit(*orbit);
    if (lookAt) camera.pose = readLookAt(*lookAt);
    if (const auto frame = section.optionalMember("frame"))
        camera.framing = frame->name<Framing>(framingFromString, framingNames());
    if (const auto fov = section.optionalMember("fov_deg")) camera.fovDeg = readKeyNumber(*fov);
    if (const auto projection = section.optionalMember("projection"))
        camera.projection = projection->name<Projection>(projectionFromString, projectionNames());
}

// "orientation": "data", "auto" or three signed axes ["+x", "+z", "-y"] that make a rotation.
Orientation readOrientation(const JsonField& field) {
    Orientation orientation;
    if (field.isString()) {
        const std::string mode = field.string();
        if (mode == "data") return orientation;
        if (mode == "auto") {
            orientation.mode = Orientation::Mode::Auto;
            return orientation;
        }
        field.fail("unknown value \"" + mode + "\"; allowed: \"data\", \"auto\" or three axes such as "
                   "[\"+x\", \"+z\", \"-y\"]");
    }
    if (field.arraySize() != 3)
        field.fail("expected three axes (display x, y, z), got " + std::to_string(field.arraySize()));
    orientation.mode = Orientation::Mode::Axes;
    std::array<bool, 3> used{};
    for (std::size_t i = 0; i < 3; ++i) {
        const JsonField entry = field.element(i);
        const std::string text = entry.string();
        const auto axis = signedAxisFromString(text);
        if (!axis) entry.fail("expected +x, -x, +y, -y, +z or -z, got \"" + text + "\"");
        if (used[std::size_t(axis->axis)]) field.fail("names an axis twice");
        used[std::size_t(axis->axis)] = true;
        orientation.axes[i] = *axis;
    }
    if (glm::determinant(rotationOf(orientation.axes)) < 0.0)
        field.fail("mirrors the data (a left-handed frame); negate one axis");
    return orientation;
}

// "aspect": "physical", "cubic", "auto" or a scale per display axis [sx, sy, sz].
Aspect readAspect(const JsonField& field) {
    Aspect aspect;
    if (field.isString()) {
        const std::string mode = field.string();
        if (mode == "physical") return aspect;
        aspect.mode = mode == "cubic" ? Aspect::Mode::Cubic : mode == "auto" ? Aspect::Mode::Auto : Aspect::Mode::Scale;
        if (aspect.mode == Aspect::Mode::Scale)
            field.fail("unknown value \"" + mode + "\"; allowed: \"physical\", \"cubic\", \"auto\" or a scale per "
                       "axis [sx, sy, sz]");
        return aspect;
    }
    aspect.mode = Aspect::Mode::Scale;
    aspect.scale = field.vec3(aboveZero);
    return aspect;
}

void readDisplay(const JsonField& root, DisplaySettings& display) {
    if (const auto orientation = root.optionalMember("orientation"))
        display.orientation = readOrientation(*orientation);
    if (const auto aspect = root.optionalMember("aspect")) display.aspect = readAspect(*aspect);
    if (const auto exaggeration = root.optionalMember("vertical_exaggeration")) {
        if (exaggeration->isString() && exaggeration->string() == "auto")
            display.verticalExaggeration.reset();
        else if (exaggeration->isString())
            exaggeration->fail("expected a number > 0 or \"auto\", got \"" + exaggeration->string() + "\"");
        else
            display.verticalExaggeration = readKeyNumber(*exaggeration);
    }
}

// The dataset need not exist yet: the dataset loader reports a missing one, naming the manifest.
std::filesystem::path readDataset(const JsonField& root, const std::filesystem::path& origin) {
    const JsonField dataset = root.member("dataset", "missing; a scene must name its dataset (a series manifest)");
    const std::filesystem::path datasetPath = dataset.pathName();
    if (datasetPath.empty()) dataset.fail("must not be empty");
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
    // Comments are allowed so that hand-written scenes can explain themselves.
    const json document = parseJsonText(text, origin, JsonComments::Allowed);
    const JsonField root(origin, document, "");
    root.allowOnlyKeys({"dataset", "image", "camera", "raycast", "stf", "compositor", "ray", "tstf", "final", "orientation",
                        "aspect", "vertical_exaggeration", "exposure", "annotations", "animation", "probes"});

    Scene scene;
    scene.dataset = readDataset(root, origin);
    readDisplay(root, scene.display);
    if (const auto image = root.optionalMember("image")) readImage(*image, scene);
    if (const auto camera = root.optionalMember("camera")) readCamera(*camera, scene.camera);
    if (const auto raycast = root.optionalMember("raycast")) readRaycast(*raycast, scene);
    if (const auto stf = root.optionalMember("stf")) readStf(*stf, scene);
    if (const auto compositor = root.optionalMember("compositor")) readCompositor(*compositor, origin, scene);
    if (const auto ray = root.optionalMember("ray")) readRay(*ray, scene);
    if (const auto problem = rayModeProblem(scene)) throwInputError(origin, problem->key, problem->problem);
    if (const auto tstf = root.optionalMember("tstf")) readTstf(*tstf, scene);
    if (const auto exposure = root.optionalMember("exposure")) readExposure(*exposure, scene.exposure);
    if (const auto finalMode = root.optionalMember("final"))
        scene.finalMode = finalMode->name<FinalMode>(finalModeFromString, finalModeNames());
    if (const auto annotations = root.optionalMember("annotations")) scene.annotations = readAnnotations(*annotations);
    if (const auto probes = root.optionalMember("probes")) scene.probes = readProbes(*probes);
    resolveStyleFiles(scene, origin);
    // Last: its keys are checked against the scene read so far.
    if (const auto animation = root.optionalMember("animation"))
        scene.animation = readAnimation(*animation, scene, origin);
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
