// The automatic scene and the fitting of a scene's automatic parts (automatic_scene.h).
#include "tstyles/scene/automatic_scene.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "tstyles/scene/automatic_opacity.h"
#include "tstyles/scene/automatic_step.h"
#include "tstyles/scene/boundary_gradient.h"
#include "tstyles/scene/temporal_change.h"
#include "tstyles/scene/temporal_compositors.h"
#include "tstyles/scene/visible_bounds.h"
#include "tstyles/scene/time_colours.h"

namespace tstyles {
namespace {

// The neutral lit-sphere style that gives the first picture its shading.
constexpr const char* kNeutralStyle = "matte-white";
// Unchanged places keep this share of the STF's opacity on their boundaries (a quarter of it inside
// regions of one value): a faint ghost of the data's structure around what changes.
constexpr double kUnchangedOpacity = 0.35;
// How far below zero an intensity image's values may reach, as a share of its largest: noise.
constexpr double kIntensityNoiseBelowZero = 0.02;
// A slab: an extent this share of the others' or less; it is seen across its thin axis.
constexpr double kSlabShare = 1.0 / 3.0;

struct AutomaticCamera {
    OrbitCamera orbit;
    Projection projection = Projection::Perspective;
    std::string reason;  // for `info`
};

std::string number(double value) {
    std::ostringstream text;
    text << std::setprecision(3) << value;
    return text.str();
}

bool isGeographic(AxisDirection direction) {
    return direction >= AxisDirection::East && direction <= AxisDirection::Down;
}

bool isAnatomical(AxisDirection direction) {
    return direction >= AxisDirection::Right && direction <= AxisDirection::Inferior;
}

// The values of the series' value range at a density, for messages.
double rawValue(const Series& series, double density) {
    return series.valueRange[0] + density * (series.valueRange[1] - series.valueRange[0]);
}

// The window as the mode's STF has it (automaticRayWindow): where its ramp starts and ends.
std::string windowText(const Series& series, const OpacityWindow& window, AutomaticStf stf) {
    const bool everyPlace = stf == AutomaticStf::EveryPlace;
    std::string text = "opacity: 0 at " + number(rawValue(series, window.low)) +
                       (everyPlace ? "" : " (5th percentile)") + " rising to " + number(window.peak) + " at " +
                       number(rawValue(series, window.high)) +
                       (everyPlace               ? " (5th percentile) and above: every place the data holds shows"
                        : window.high == 1.0 ? " (the largest value)"
                                             : " (99th percentile)");
    if (window.background)
        text += "; background " + number(rawValue(series, (*window.background)[0])) + " .. " +
                number(rawValue(series, (*window.background)[1])) + " (" +
                number(100.0 * window.backgroundFraction) + " % of the values) transparent";
    return text;
}

// The display axis along which the data is a slab (its extent a third of the others' or less, in
// the aspect's proportions before any vertical exaggeration: an extremely thin axis that the
// exaggeration thickens to a quarter of the width is still a slab); none for a block.
std::optional<int> slabAxis(const Series& series, const DisplayFrame& frame) {
    glm::dvec3 extent = glm::abs(frame.rotation * series.worldBounds().size()) * frame.scale;
    extent.y /= frame.verticalExaggeration;
    int thin = 0;
    for (int axis = 1; axis < 3; ++axis)
        if (extent[axis] < extent[thin]) thin = axis;
    const double others = std::min(extent[(thin + 1) % 3], extent[(thin + 2) % 3]);
    if (!(extent[thin] > 0.0) || extent[thin] > kSlabShare * others) return std::nullopt;
    return thin;
}

// How a slab thin along each display axis (x, y, z) is seen: at its large face.
struct SlabView {
    double azimuthDeg;
    double elevationDeg;
    double anatomicalAzimuthDeg;  // from above, the image's top is display -z at azimuth 0, +z (anterior) at 180
    const char* reason;
    const char* anatomicalReason;
};
constexpr SlabView kSlabViews[3] = {
    {90.0, 0.0, 90.0, "a slab, thin across: seen from the side",
     "an anatomical slab, thin from side to side: seen from the side (sagittal), head up"},
    {0.0, 90.0, 180.0, "a slab, thin along the vertical: seen from above",
     "an anatomical slab, thin from head to foot: seen from above (axial), anterior at the top"},
    {0.0, 0.0, 0.0, "a slab, thin toward the viewer: seen from the front",
     "an anatomical slab, thin from front to back: seen from the front (coronal), head up"}};

// Geographic data straight from above, north up, orthographic, as a map is read (the surface first
// along the rays; from an oblique angle a deep, exaggerated column's south wall filled the picture). A slab
// across its thin axis, at its large face: from above (anatomical: an axial view, anterior at the
// top), from the front, or from the side (display +x). Other anatomical data from the front, head
// up; anything else from an oblique three-quarter view.
AutomaticCamera automaticCamera(DataKind kind, const Series& series, const DisplayFrame& frame) {
    AutomaticCamera camera;
    OrbitCamera& orbit = camera.orbit;
    const std::optional<int> slab = slabAxis(series, frame);
    if (kind == DataKind::Geographic) {
        orbit.azimuthDeg = 0.0;
        orbit.elevationDeg = 90.0;
        // Parallel rays, as a map is drawn: a perspective's rays lean out by up to half its field
        // of view, and through a column exaggerated to a quarter of the map's width they passed
        // under the coasts and showed the deep water beside them as a grey rim on one side of
        // every continent.
        camera.projection = Projection::Orthographic;
        camera.reason = "geographic: seen from above, north up, orthographic (parallel rays, as a map is drawn)";
    } else if (slab) {
        const SlabView& view = kSlabViews[std::size_t(*slab)];
        const bool anatomical = kind == DataKind::Anatomical;
        orbit.azimuthDeg = anatomical ? view.anatomicalAzimuthDeg : view.azimuthDeg;
        orbit.elevationDeg = view.elevationDeg;
        camera.reason = anatomical ? view.anatomicalReason : view.reason;
    } else if (kind == DataKind::Anatomical) {
        orbit.azimuthDeg = 0.0;
        orbit.elevationDeg = 0.0;
        camera.reason = "anatomical: seen from the front, head up";
    } else {
        camera.reason = "no axis meaning in the file: an oblique three-quarter view";
    }
    return camera;
}

// Lengths of a microscope's scale: micrometres or nanometres, as the readers spell them.
bool hasMicroscopeAxes(const Series& series) {
    return std::any_of(series.axes.begin(), series.axes.end(),
                       [](const SpatialAxis& axis) { return axis.unit == "um" || axis.unit == "nm"; });
}

}  // namespace

std::pair<RayMode, std::string> automaticRayMode(const Series& series) {
    const DataKind kind = dataKindOf(series);
    if (kind == DataKind::Geographic)
        return {rayModeNamed("largest-change"),
                "ray: largest-change (the sample along each ray whose values change most over time): a map seen from "
                "above shows each place at the depth where it changes most, in the colour of its time, not a mix of "
                "every layer"};
    const bool imagingAxes = kind == DataKind::Anatomical || hasMicroscopeAxes(series);
    // Intensities are not below zero; noise around a zero background (or its interpolation) may dip
    // a little under it, while CT's Hounsfield units reach -1000 against a few thousand.
    const bool intensities = series.valueRange[0] >= -kIntensityNoiseBelowZero * std::abs(series.valueRange[1]);
    if (imagingAxes && intensities)
        return {rayModeNamed("maximum"),
                "ray: maximum (the brightest place along each ray): intensities that are not below zero on " +
                    std::string(kind == DataKind::Anatomical ? "anatomical" : "a microscope's") +
                    " axes (MR, fMRI, PET, microscopy) have no surface for compositing to find"};
    const std::string why = imagingAxes ? "values well below 0 (CT's Hounsfield units: tissues with boundaries)"
                                        : "no imaging axes (a simulation, a map)";
    return {kCompositeRay, "ray: composite (front to back): " + why};
}

namespace {

// A projection of values shows one sample per pixel: the unchanged places keep the STF's whole
// opacity (the anatomy in grey, time in colour where it changes, as an fMRI overlay shows it); a
// composited ray sees through their faint share to what changes; where the STF is opaque at every
// place (the largest change), the faint share tells them from the time colours (June's white).
double automaticUnchangedOpacity(RayMode mode) {
    return rayModeInfo(mode).automaticStf == AutomaticStf::LargestValue ? 1.0 : kUnchangedOpacity;
}

// The smallest ramp's width, in density: a window whose 5th percentile is the smallest value.
constexpr double kNarrowestRamp = 1.0 / kOpacityHistogramBins;

// The window a mode's STF ramps over. Where one sample of the largest value makes the pixel, up to
// an opacity of 1, and up to the largest value instead of the 99th percentile: the largest values
// along the rays lie near the top of the data's range, and would all be white. Where one sample of
// any value does (the largest change), opaque from the 5th percentile up, rising from the smallest
// value (or the background's top): every place the data holds shows.
OpacityWindow automaticRayWindow(const OpacityWindow& window, RayMode mode) {
    OpacityWindow shown = window;
    switch (rayModeInfo(mode).automaticStf) {
        case AutomaticStf::RayThrough: break;
        case AutomaticStf::LargestValue:
            shown.peak = 1.0;
            shown.high = 1.0;
            break;
        case AutomaticStf::EveryPlace: {
            shown.peak = 1.0;
            shown.high = std::max(window.low, kNarrowestRamp);
            const double floor = window.background ? (*window.background)[1] : 0.0;
            shown.low = floor < shown.high ? floor : 0.0;
            shown.low = std::min(shown.low, shown.high - kNarrowestRamp);
            break;
        }
    }
    return shown;
}

// applyAutomaticRay with the display frame the series is seen in.
void applyAutomaticRayIn(Scene& scene, const Series& series, const DisplayFrame& frame, const OpacityWindow& window,
                         RayMode mode) {
    if (const auto step = automaticStep(series, frame, mode)) scene.raycast.step = *step;
    const bool projection = rayModeInfo(mode).automaticStf != AutomaticStf::RayThrough;
    if (auto& unchanged = scene.compositorOptions.unchanged) unchanged->opacity = automaticUnchangedOpacity(mode);
    const OpacityWindow shown = automaticRayWindow(window, mode);
    scene.rayMode = mode;
    scene.stf.curve.opacity = opacityNodes(shown);
    scene.stf.curve.color = {ColorNode{0.0, glm::dvec3(1.0), projection ? "" : kNeutralStyle}};
}

}  // namespace

void applyAutomaticRay(Scene& scene, const Series& series, const OpacityWindow& window, RayMode mode) {
    applyAutomaticRayIn(scene, series, chooseDisplayFrame(scene.display, series), window, mode);
}

void applyAutomaticRayToShown(Scene& scene, const Series& shown, const OpacityWindow& window, RayMode mode) {
    applyAutomaticRayIn(scene, shown, DisplayFrame{}, window, mode);
}

DataKind dataKindOf(const Series& series) {
    bool geographic = false;
    bool anatomical = false;
    for (const SpatialAxis& axis : series.axes) {
        geographic = geographic || isGeographic(axis.direction);
        anatomical = anatomical || isAnatomical(axis.direction);
    }
    return geographic ? DataKind::Geographic : anatomical ? DataKind::Anatomical : DataKind::Other;
}

double typicalLargestChange(const Series& series, const Stf& stf) {
    return typicalOf(temporalChanges(series, stf).changes);
}

AutomaticScene automaticScene(const Series& series, const std::filesystem::path& dataset) {
    return automaticScene(series, dataset, automaticOpacityWindow(series));
}

AutomaticScene automaticScene(const Series& series, const std::filesystem::path& dataset, const OpacityWindow& window,
                              RenderedBy renderedBy) {
    AutomaticScene result;
    Scene& scene = result.scene;
    scene.dataset = dataset;
    scene.display.orientation.mode = Orientation::Mode::Auto;
    scene.display.aspect.mode = Aspect::Mode::Auto;
    scene.display.verticalExaggeration.reset();
    const DisplayFrame frame = chooseDisplayFrame(scene.display, series);
    result.explanation = frame.explanation;

    const DataKind kind = dataKindOf(series);
    const AutomaticCamera camera = automaticCamera(kind, series, frame);
    scene.camera.pose = camera.orbit;
    scene.camera.projection = camera.projection;
    scene.camera.framing = Framing::Visible;
    result.explanation.push_back("camera: " + camera.reason + ", framed on the visible data");
    // A map's land is the missing values at its surface: the coast drawn where they meet the data.
    scene.annotations.coast = kind == DataKind::Geographic;
    if (kind == DataKind::Geographic)
        result.explanation.push_back("coast: a line where the surface's missing values (land) meet its data");

    auto [rayMode, rayReason] = automaticRayMode(series);
    if (renderedBy == RenderedBy::MergedBlocks && rayModeInfo(rayMode).merge != RayMerge::Over) {
        rayReason = "ray: composite (the file would open in " + toString(rayMode) +
                    ", but --distributed merges the processes' frames front to back, which holds for composite)";
        rayMode = kCompositeRay;
    }
    applyAutomaticRay(scene, series, window, rayMode);
    result.explanation.push_back(rayReason);
    if (scene.raycast.step) {
        const bool beams = std::any_of(series.steps.begin(), series.steps.end(), [](const TimeStep& s) { return s.isBeam(); });
        const std::string cell = rayModeInfo(rayMode).automaticStepInCells == 1.0 ? "the typical cell" : "half the typical cell";
        result.explanation.push_back("ray step: " + number(*scene.raycast.step) + " (" +
                                     (beams ? "one range cell of the beams, or " + cell + " of other grids"
                                            : cell + ": the lower quartile of the spacings along each axis") +
                                     ")");
    }
    result.explanation.push_back(windowText(series, automaticRayWindow(window, rayMode), rayModeInfo(rayMode).automaticStf));
    result.explanation.push_back(scene.stf.curve.color.front().style.empty()
                                     ? std::string("shading: none (a projection has no surface to shade)")
                                     : std::string("shading: the lit-sphere style ") + kNeutralStyle + " on the STF");

    scene.compositor = compositorNamed("temporal-mip");
    scene.finalMode = FinalMode::Modulate;
    scene.indexTstf.curve.opacity = {OpacityNode{0.0, 1.0}};
    scene.gradientTstf.automaticRange = true;
    applyTimeColours(scene, series.size());
    result.explanation.push_back("time: " + timeColoursText(series.size()) +
                                 "; compositor temporal-mip (each place shows the time-step where it is most opaque)");
    scene.compositorOptions.unchanged = UnchangedTime{};
    const std::string threshold =
        " where a place's values change by no more than a threshold fitted to the data (a tenth of the typical "
        "largest change, or above the noise); no time colour where two time-steps tie";
    scene.compositorOptions.unchanged->opacity = automaticUnchangedOpacity(scene.rayMode);
    const AutomaticStf stf = rayModeInfo(scene.rayMode).automaticStf;
    if (stf == AutomaticStf::LargestValue) {
        result.explanation.push_back("unchanged places: no time colour, the STF's grey" + threshold);
    } else if (stf == AutomaticStf::EveryPlace) {
        result.explanation.push_back("unchanged places: no time colour, a faint grey (" + number(kUnchangedOpacity) +
                                     " of the opacity)" + threshold);
    } else {
        result.explanation.push_back("unchanged places: no time colour and " + number(kUnchangedOpacity) +
                                     " of the opacity on boundaries (a quarter of that inside regions of one value)" +
                                     threshold + "; what changes as opaque as the STF makes a ray through all the data");
    }
    return result;
}

Bounds framedBounds(const Scene& scene, const Series& series) {
    return scene.camera.framing == Framing::Visible ? visibleBounds(series, scene.stf) : series.worldBounds();
}

std::pair<double, double> automaticGradientRange(const Scene& scene, const Series& series) {
    return gradientRangeForChange(scene, series, typicalLargestChange(series, scene.stf));
}

namespace {

// The whole fit: the thresholds from the places' changes, the boundary from the value gradient.
UnchangedFit unchangedFitOn(const PlaceChanges& places, const Series& series, const Stf& stf) {
    UnchangedFit fit = unchangedFitOf(places, series.size());
    fit.boundary = boundaryGradientOf(gradientMagnitudes(series, stf));
    return fit;
}

}  // namespace

UnchangedFit automaticUnchangedFit(const Scene& scene, const Series& series) {
    return unchangedFitOn(temporalChanges(series, scene.stf), series, scene.stf);
}

std::pair<double, double> gradientRangeForChange(const Scene& scene, const Series& series, double change) {
    switch (compositorInfo(scene.compositor).range) {
        case AutomaticRange::Change: return {0.0, change};
        case AutomaticRange::HalfChange: return {0.0, 0.5 * change};
        case AutomaticRange::SignedChange: return {-change, change};
        case AutomaticRange::SignedPerTime: {
            const double span = series.steps.back().time - series.steps.front().time;
            const double perTime = span > 0.0 ? change / span : change;
            return {-perTime, perTime};
        }
    }
    return {0.0, change};
}

Scene fitAutomaticParts(Scene scene, const Series& display) {
    const bool fitsUnchanged = scene.compositorOptions.unchanged && scene.compositorOptions.unchanged->automatic;
    if (!scene.gradientTstf.automaticRange && !fitsUnchanged) return scene;
    const PlaceChanges places = temporalChanges(display, scene.stf);
    if (scene.gradientTstf.automaticRange) {
        const auto [low, high] = gradientRangeForChange(scene, display, typicalOf(places.changes));
        scene.gradientTstf.rangeLow = low;
        scene.gradientTstf.rangeHigh = high;
    }
    if (fitsUnchanged) takeFit(*scene.compositorOptions.unchanged, unchangedFitOn(places, display, scene.stf));
    return scene;
}

SceneOnSeries fitSceneToSeries(Scene scene, Series series) {
    const DisplayFrame frame = chooseDisplayFrame(scene.display, series);
    Series display = applyDisplayFrame(std::move(series), frame);
    scene = fitAutomaticParts(std::move(scene), display);
    const Bounds framed = framedBounds(scene, display);
    return {std::move(scene), std::move(display), frame, framed};
}

}  // namespace tstyles
