// The automatic scene: what `tstyles render DATASET`, `tstyles view DATASET` and `tstyles scene`
// make of a dataset with no scene file, and how the automatic parts of any scene are fitted to the
// series it meets. A documented, deterministic function of the data (docs/automatic-scene.md).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tstyles/data/display_frame.h"
#include "tstyles/data/series.h"
#include "tstyles/scene/automatic_opacity.h"
#include "tstyles/scene/scene.h"
#include "tstyles/scene/temporal_change.h"

namespace tstyles {

// What the file says the data is, from its axes' directions.
enum class DataKind { Geographic, Anatomical, Other };
DataKind dataKindOf(const Series& series);

struct AutomaticScene {
    Scene scene;
    // One line per choice, for `tstyles info`, `tstyles scene` and the viewer.
    std::vector<std::string> explanation;
};

// The scene for a series as read (before any display frame): display frame, opacity from the
// histogram, a neutral lit-sphere style, time in colour, the compositor and the camera.
AutomaticScene automaticScene(const Series& series, const std::filesystem::path& dataset);
// The same with the opacity window given: `series` may then be an outline (no values), as where
// each process of a distributed render reads only its block and the window is taken from them all.
// RenderedBy::MergedBlocks: the frames of processes that each render a block are merged front to back
// (`--distributed`), so the ray composites where the automatic mode would not merge.
enum class RenderedBy { OneProcess, MergedBlocks };
AutomaticScene automaticScene(const Series& series, const std::filesystem::path& dataset, const OpacityWindow& window,
                              RenderedBy renderedBy = RenderedBy::OneProcess);

// The ray mode of the automatic scene: largest-change for maps (geographic data, seen from above:
// each place at the depth where it changes most); maximum for intensity images (values not below zero, beyond
// noise of 2 % of the largest, on anatomical axes or a microscope's: MR, fMRI, PET, fluorescence
// microscopy), where compositing the
// whole volume gives a fog with no boundary in it; composite for everything else (CT, whose
// Hounsfield units go negative, simulations, maps). With the reason in words.
std::pair<RayMode, std::string> automaticRayMode(const Series& series);
// The automatic STF for a ray mode, with the mode: the window's ramp, rising to its peak where the
// pixel composites a ray through all the data, to 1 and without the shading style where it takes
// one sample's opacity (maximum, minimum, average: a projection has no surface to shade); and the
// mode's automatic ray step (automaticStep).
void applyAutomaticRay(Scene& scene, const Series& series, const OpacityWindow& window, RayMode mode);
// The same for a series already turned into the scene's display frame (the window's): its step is
// the shown grids' typical cell.
void applyAutomaticRayToShown(Scene& scene, const Series& shown, const OpacityWindow& window, RayMode mode);

// A scene fitted to a series: the series turned and scaled into the display frame the scene asks
// for, the automatic gradient range filled in, and the bounds an automatic camera frames.
struct SceneOnSeries {
    Scene scene;
    Series series;  // in display coordinates
    DisplayFrame frame;
    Bounds framed;  // visible or whole-series bounds, as the camera's framing says
};

SceneOnSeries fitSceneToSeries(Scene scene, Series series);

// The second half of fitSceneToSeries, for front ends that keep a series already turned into the
// scene's display frame across frames (the Python module): the automatic gradient range and the
// automatic unchanged-place threshold (CompositorOptions::unchanged) filled in.
Scene fitAutomaticParts(Scene scene, const Series& display);

// The bounds an automatic orbit camera frames for this scene on this (display) series.
Bounds framedBounds(const Scene& scene, const Series& series);

// The change (max - min density over time-steps) below which 99 % of the visible voxels' changes
// lie: the automatic gradient TSTF range is [0, this].
double typicalLargestChange(const Series& series, const Stf& stf);
// The thresholds of unchanged places on the (display) series where the scene's are "auto"
// (unchangedFitOf over the places the scene's STF shows).
UnchangedFit automaticUnchangedFit(const Scene& scene, const Series& series);
// The gradient TSTF's range that "auto" stands for with the scene's compositor
// (AutomaticRange of tstyles/scene/temporal_compositors.h).
std::pair<double, double> automaticGradientRange(const Scene& scene, const Series& series);
// The same for a typical largest change already known (`series` gives the time span).
std::pair<double, double> gradientRangeForChange(const Scene& scene, const Series& series, double change);
// The automatic scene's gradient TSTF colours and opacities for the scene's compositor: for a
// signed one (linear-trend, difference) the diverging "blue-red", faint in the middle (no change);
// else the paper's "green-orange", faint at 0. For a compositor chosen after the automatic scene;
// returns the choice in words.
std::string applyAutomaticGradientColours(Scene& scene);

}  // namespace tstyles
