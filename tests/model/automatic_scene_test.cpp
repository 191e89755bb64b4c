// The automatic scene's choices on realistic files (tests/data/realistic_datasets.h), read through
// the readers: the opacity window from the histogram, the camera by data kind, and a scene that
// survives being written and read back.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "../data/realistic_datasets.h"
#include "tstyles/data/manifest.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/scene/automatic_opacity.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/automatic_step.h"
#include "tstyles/scene/ray_mode_switch.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles {
namespace {

std::filesystem::path sampleFolder() {
    static const auto folder = [] {
        auto path = std::filesystem::temp_directory_path() / ("tstyles_automatic_model_" + std::to_string(::getpid()));
        std::filesystem::create_directories(path);
        return path;
    }();
    return folder;
}

double densityOf(const Series& series, double value) {
    return (value - series.valueRange[0]) / (series.valueRange[1] - series.valueRange[0]);
}

TEST(AutomaticScene, CtAirIsTransparentAndBoneOpaqueFromTheFront) {
    const auto file = sampleFolder() / "ct.nii";
    testdata::writeCtPhantom(file);
    const Series series = openSeries(file, ReadOptions{});
    const AutomaticScene automatic = automaticScene(series, file);
    const TransferFunction1D& stf = automatic.scene.stf.curve;
    EXPECT_EQ(stf.evaluate(densityOf(series, -1000.0)).opacity, 0.0) << "air";
    EXPECT_EQ(stf.evaluate(densityOf(series, -990.0)).opacity, 0.0) << "air with noise";
    EXPECT_GT(stf.evaluate(densityOf(series, 40.0)).opacity, 0.0) << "soft tissue";
    EXPECT_GT(stf.evaluate(densityOf(series, 700.0)).opacity, stf.evaluate(densityOf(series, 40.0)).opacity)
        << "bone over soft tissue";
    EXPECT_EQ(dataKindOf(series), DataKind::Anatomical);
    const auto& orbit = std::get<OrbitCamera>(automatic.scene.camera.pose);
    EXPECT_EQ(orbit.azimuthDeg, 0.0);
    EXPECT_EQ(orbit.elevationDeg, 0.0);
    EXPECT_EQ(automatic.scene.camera.framing, Framing::Visible);
}

// Issue 50: intensity images (not below zero beyond noise, on anatomical axes) open as a maximum
// projection, STF up to 1 without a style and unchanged places at the STF's whole opacity; CT,
// whose air is -1000 HU, composites with the neutral style. Issue 51: maps show the largest
// change along each column, unshaded, every place opaque, unchanged ones a faint grey.
TEST(AutomaticScene, IntensityImagesAreMaximumProjectionsCtCompositesAndMapsShowTheLargestChange) {
    struct Case {
        const char* name;
        void (*write)(const std::filesystem::path&);
        const char* mode;
    };
    for (const Case& c : {Case{"fmri.nii", testdata::writeFmriRun, "maximum"},
                          Case{"follow-up.nii", testdata::writeBrainFollowUp, "maximum"},
                          Case{"blob.nii", testdata::writeMovingBlobNifti, "maximum"},
                          Case{"ct.nii", testdata::writeCtPhantom, "composite"},
                          Case{"perfusion.nii", testdata::writeCtHeadPerfusion, "composite"},
                          Case{"eddy.nc", testdata::writeOceanEddy, "largest-change"},
                          Case{"climatology.nc", testdata::writeOceanClimatology, "largest-change"},
                          Case{"forecast.nc", testdata::writeRegionalForecast, "largest-change"}}) {
        SCOPED_TRACE(c.name);
        const auto file = sampleFolder() / c.name;
        c.write(file);
        const Series series = openSeries(file, ReadOptions{});
        const AutomaticScene automatic = automaticScene(series, file);
        const Scene& scene = automatic.scene;
        EXPECT_EQ(toString(automaticRayMode(series).first), c.mode);
        EXPECT_EQ(toString(scene.rayMode), c.mode);
        const bool maximum = std::string(c.mode) == "maximum";
        const bool largestChange = std::string(c.mode) == "largest-change";
        double peak = 0.0;
        for (const OpacityNode& node : scene.stf.curve.opacity) peak = std::max(peak, node.opacity);
        if (maximum || largestChange) {
            EXPECT_EQ(peak, 1.0) << "one sample makes the pixel: the STF rises to 1";
        }
        EXPECT_EQ(scene.stf.curve.color.front().style.empty(), maximum || largestChange);
        EXPECT_EQ(scene.compositorOptions.unchanged->opacity, maximum ? 1.0 : 0.35);
        if (largestChange) {
            // Opaque from the 5th percentile up: the median of the values above the smallest (the
            // forecast's clear air is 0) shows whole.
            std::vector<float> values;
            for (const TimeStep& step : series.steps)
                for (std::size_t i = 0; i < step.density.size(); i += 97)
                    if (step.density[i] > 0.0f) values.push_back(step.density[i]);
            std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
            EXPECT_EQ(scene.stf.curve.evaluate(values[values.size() / 2]).opacity, 1.0) << "the median value";
        }
        const bool said = std::any_of(automatic.explanation.begin(), automatic.explanation.end(),
                                      [&](const std::string& line) { return line.rfind(std::string("ray: ") + c.mode, 0) == 0; });
        EXPECT_TRUE(said) << "the explanation names the mode";
    }
    // The follow-up's noise dips below zero (-3 against 1162): still an intensity image.
    const Series followUp = openSeries(sampleFolder() / "follow-up.nii", ReadOptions{});
    EXPECT_LT(followUp.valueRange[0], 0.0);
}

TEST(AutomaticScene, VisibleBoundsLeaveTheAirOut) {
    const auto file = sampleFolder() / "blob.nii";
    testdata::writeMovingBlobNifti(file);
    const Series series = openSeries(file, ReadOptions{});
    const Scene scene = automaticScene(series, file).scene;
    const Bounds visible = framedBounds(scene, series);
    const Bounds all = series.worldBounds();
    // The blobs span x 6 .. 50 voxels of 3 mm and y, z 16 .. 24 around the middle: far less than the volume.
    EXPECT_LT(visible.size().y, 0.3 * all.size().y);
    EXPECT_NEAR(visible.size().x, 44.0 * 3.0, 3.0 * 3.0);
}

TEST(AutomaticScene, WrittenAndReadBackIsTheSameScene) {
    const auto file = sampleFolder() / "ocean.nc";
    testdata::writeOceanAnomalies(file);
    const Series series = openSeries(file, ReadOptions{});
    const Scene scene = automaticScene(series, std::filesystem::absolute(file)).scene;
    const auto sceneFile = sampleFolder() / "ocean.json";
    saveScene(scene, sceneFile);
    EXPECT_EQ(loadScene(sceneFile), scene);
    EXPECT_EQ(dataKindOf(series), DataKind::Geographic);
}

// A map is seen straight from above with north up: the view looks down the display's up axis, and
// the image's up is north (display -z: the frame puts north away from a camera at azimuth 0).
TEST(AutomaticScene, AMapIsSeenFromAboveWithNorthUp) {
    const auto file = sampleFolder() / "ocean-map.nc";
    testdata::writeOceanAnomalies(file);
    const Series series = openSeries(file, ReadOptions{});
    const SceneOnSeries fitted = fitSceneToSeries(automaticScene(series, file).scene, series);
    const View view = resolveView(fitted.scene.camera, fitted.framed, fitted.series.worldBounds(), 400, 300);
    const glm::dvec3 looking = glm::normalize(view.target - view.eye);
    EXPECT_NEAR(looking.y, -1.0, 1e-9);
    EXPECT_NEAR(view.up.z, -1.0, 1e-9);
    EXPECT_NEAR(std::abs(view.up.x) + std::abs(view.up.y), 0.0, 1e-9);
}

TEST(AutomaticScene, GradientRangeIsFittedToTheChangePresent) {
    const auto file = sampleFolder() / "blob-change.nii";
    testdata::writeMovingBlobNifti(file);
    const SceneOnSeries fitted = fitSceneToSeries(automaticScene(openSeries(file, ReadOptions{}), file).scene,
                                                  openSeries(file, ReadOptions{}));
    // Where a blob is, one time-step holds 100 and the others 0: the change is the whole range.
    EXPECT_DOUBLE_EQ(fitted.scene.gradientTstf.rangeLow, 0.0);
    EXPECT_DOUBLE_EQ(fitted.scene.gradientTstf.rangeHigh, 1.0);
}

// NRRD's `space` names the world axes' directions: LPS (DICOM's) shows the patient facing the
// viewer, their left on the image's right.
TEST(AutomaticScene, NrrdSpaceGivesTheAnatomicalOrientation) {
    const auto file = sampleFolder() / "lps.nrrd";
    {
        std::ofstream out(file, std::ios::binary);
        out << "NRRD0004\ntype: short\ndimension: 3\nspace: left-posterior-superior\nsizes: 4 5 6\n"
               "space directions: (1,0,0) (0,1,0) (0,0,2)\nspace units: \"mm\" \"mm\" \"mm\"\nencoding: raw\n"
               "endian: little\n\n";
        for (int i = 0; i < 4 * 5 * 6; ++i) {
            const std::int16_t value = std::int16_t(i);
            out.write(reinterpret_cast<const char*>(&value), sizeof value);
        }
    }
    const Series series = openSeries(file, ReadOptions{});
    EXPECT_EQ(series.axes[0].direction, AxisDirection::Left);
    EXPECT_EQ(series.axes[1].direction, AxisDirection::Posterior);
    EXPECT_EQ(series.axes[2].unit, "mm");
    const DisplayFrame frame = chooseDisplayFrame(automaticScene(series, file).scene.display, series);
    EXPECT_EQ(frame.rotation * glm::dvec3(1, 0, 0), glm::dvec3(1, 0, 0));   // left -> the image's right
    EXPECT_EQ(frame.rotation * glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1));  // posterior -> away from the viewer
    EXPECT_EQ(frame.rotation * glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0));   // superior -> up
}


// What a distributed render starts from where each process reads only its block: the automatic
// scene of a manifest's outline (no values) with the opacity window given is the whole series'
// scene, and fitting it to the outline reads no value (the parts that need them are fitted over
// the blocks, src/distributed): visible framing frames the whole series, the change is 1.
TEST(AutomaticScene, AnOutlineWithTheWindowGivesTheSceneAndReadsNoValue) {
    const std::filesystem::path manifest = std::filesystem::path(TSTYLES_SOURCE_DIR) / "data/hurricane/series.json";
    const Series series = loadSeries(manifest);
    const Series outline = loadSeriesOutline(manifest);
    const Scene whole = automaticScene(series, manifest).scene;
    const Scene fromOutline = automaticScene(outline, manifest, automaticOpacityWindow(series)).scene;
    EXPECT_EQ(fromOutline.stf.curve.opacity, whole.stf.curve.opacity);
    EXPECT_EQ(fromOutline.camera.framing, Framing::Visible);
    EXPECT_TRUE(fromOutline.gradientTstf.automaticRange);

    const SceneOnSeries fitted = fitSceneToSeries(fromOutline, outline);
    EXPECT_EQ(fitted.framed.lower, fitted.series.worldBounds().lower);
    EXPECT_EQ(fitted.framed.upper, fitted.series.worldBounds().upper);
    EXPECT_EQ(fitted.scene.gradientTstf.rangeHigh, 1.0);
    // With the values, the hurricane's visible part is smaller than its box, and its change below 1.
    const SceneOnSeries withValues = fitSceneToSeries(whole, series);
    EXPECT_LT(withValues.framed.size().y, withValues.series.worldBounds().size().y);
    EXPECT_LT(withValues.scene.gradientTstf.rangeHigh, 1.0);
}

}  // namespace
}  // namespace tstyles

namespace tstyles {
namespace {

// Two time-steps of a smooth field on a grid of `dims` nodes `spacing` apart, with the axes given.
Series slabSeries(glm::ivec3 dims, glm::dvec3 spacing, const std::array<SpatialAxis, 3>& axes) {
    Series series;
    series.axes = axes;
    series.valueRange = {0.0, 1.0};
    RectilinearGrid grid;
    grid.dims = dims;
    grid.spacing = spacing;
    for (int t = 0; t < 2; ++t) {
        TimeStep step;
        step.time = t;
        step.grid = grid;
        for (int z = 0; z < dims.z; ++z)
            for (int y = 0; y < dims.y; ++y)
                for (int x = 0; x < dims.x; ++x)
                    step.density.push_back(float(0.5 + 0.4 * std::sin(0.3 * x + 0.2 * y + 0.5 * z + t)));
        series.steps.push_back(std::move(step));
    }
    return series;
}

View automaticViewOf(const Series& series, std::string* cameraLine = nullptr) {
    const AutomaticScene automatic = automaticScene(series, "slab.nc");
    for (const std::string& line : automatic.explanation)
        if (cameraLine && line.rfind("camera:", 0) == 0) *cameraLine = line;
    const SceneOnSeries fitted = fitSceneToSeries(automatic.scene, series);
    return resolveView(fitted.scene.camera, fitted.framed, fitted.series.worldBounds(), 400, 300);
}

}  // namespace

// The MR slab of 24 slices (53 mm) across a 256 mm field: seen from above (looking down the
// display's up, the head-foot axis), anterior (display +z) at the image's top.
TEST(AutomaticScene, AnAxialMrSlabIsSeenFromAboveWithAnteriorAtTheTop) {
    const auto file = sampleFolder() / "mr-slab.nii";
    testdata::writeMrSlab(file);
    const Series series = openSeries(file, ReadOptions{});
    std::string cameraLine;
    const View view = automaticViewOf(series, &cameraLine);
    const glm::dvec3 looking = glm::normalize(view.target - view.eye);
    EXPECT_NEAR(looking.y, -1.0, 1e-9);
    EXPECT_NEAR(view.up.z, 1.0, 1e-9);
    EXPECT_NE(cameraLine.find("seen from above (axial), anterior at the top"), std::string::npos) << cameraLine;
}

// A slab without axis meaning is seen across its thin axis: thin toward the viewer (data z) from the
// front, thin across (data x) from the side, at the large face either way.
TEST(AutomaticScene, ASlabIsSeenAcrossItsThinAxis) {
    const std::array<SpatialAxis, 3> voxels{};
    const View front = automaticViewOf(slabSeries({60, 50, 8}, glm::dvec3(1.0), voxels));
    EXPECT_NEAR(glm::normalize(front.target - front.eye).z, -1.0, 1e-9);
    const View side = automaticViewOf(slabSeries({8, 50, 60}, glm::dvec3(1.0), voxels));
    EXPECT_NEAR(glm::normalize(side.target - side.eye).x, -1.0, 1e-9);
    // Not a slab (the thinnest over a third of the others): the oblique three-quarter view.
    const View block = automaticViewOf(slabSeries({60, 50, 30}, glm::dvec3(1.0), voxels));
    const glm::dvec3 looking = glm::normalize(block.target - block.eye);
    EXPECT_GT(std::abs(looking.x), 0.1);
    EXPECT_GT(std::abs(looking.y), 0.1);
}

// The OME-Zarr ocean of the issue: kilometres across (180 x 90 cells of 111 km), metres deep (19
// levels to 1 km), no names that say which way is up. The thin axis goes up, is exaggerated to a
// quarter of the width (19 869 km / 4 over 990 m: 5 017, 5 000 to two digits), and is seen from
// above.
TEST(AutomaticScene, AnExtremelyThinAxisGoesUpExaggeratedAndIsSeenFromAbove) {
    const std::array<SpatialAxis, 3> axes{SpatialAxis{"x", "km"}, SpatialAxis{"y", "km"}, SpatialAxis{"z", "m"}};
    const Series series = slabSeries({180, 90, 19}, {111.0, 111.0, 55.0}, axes);
    const DisplayFrame frame = chooseDisplayFrame(automaticScene(series, "ocean.zarr").scene.display, series);
    EXPECT_NE(frame.rotation[2][1], 0.0);  // display up (row 1) is the data's z (column 2)
    EXPECT_DOUBLE_EQ(frame.verticalExaggeration, 5000.0);
    const View view = automaticViewOf(series);
    EXPECT_NEAR(glm::normalize(view.target - view.eye).y, -1.0, 1e-9);
}

}  // namespace tstyles

namespace tstyles {

// The automatic step (automatic_step.h): the lower quartile of the node distances along each
// axis, the smallest over the axes, in the ray mode's share of a cell. Levels at 0, 1, 3, 6, 10, 15
// are 1, 2, 3, 4 and 5 apart: the lower quartile (the second of five) is 2, under the even axes' 5,
// so a composited ray steps 2 and a maximum projection 1, where the renderer's default would take
// half the thinnest level, 0.5. An even grid gets its spacing, or the default at half a cell.
TEST(AutomaticStep, TheLowerQuartileOfTheLevelSpacingsInTheModesShareOfACell) {
    const RayMode maximum = *rayModeFromString("maximum");
    Series series;
    RectilinearGrid grid;
    grid.dims = {4, 4, 6};
    grid.spacing = {5.0, 5.0, 1.0};
    grid.axisPositions[2] = {0.0, 1.0, 3.0, 6.0, 10.0, 15.0};
    TimeStep step;
    step.grid = grid;
    series.steps.push_back(step);
    const auto uneven = automaticStep(series, DisplayFrame{}, maximum);
    ASSERT_TRUE(uneven.has_value());
    EXPECT_DOUBLE_EQ(*uneven, 1.0);
    EXPECT_DOUBLE_EQ(*automaticStep(series, DisplayFrame{}, kCompositeRay), 2.0);
    EXPECT_DOUBLE_EQ(0.5 * series.finestSpacing(), 0.5);

    // Drawn twice as tall (a vertical exaggeration of 2 on display y, the grid's y here): y's
    // spacing becomes 10, z's quartile 2 is still the least.
    DisplayFrame tall;
    tall.scale = {1.0, 2.0, 1.0};
    EXPECT_DOUBLE_EQ(*automaticStep(series, tall, maximum), 1.0);
    DisplayFrame deep;
    deep.scale = {1.0, 1.0, 3.0};  // z drawn 3 times longer: its quartile 6, x's 5 is the least
    EXPECT_DOUBLE_EQ(*automaticStep(series, deep, maximum), 2.5);
    EXPECT_DOUBLE_EQ(*automaticStep(series, deep, kCompositeRay), 5.0);

    series.steps[0].grid = RectilinearGrid{{4, 4, 4}, {0.2, 0.3, 0.4}, {}};
    EXPECT_DOUBLE_EQ(*automaticStep(series, DisplayFrame{}, maximum), 0.5 * series.finestSpacing());
    EXPECT_DOUBLE_EQ(*automaticStep(series, DisplayFrame{}, kCompositeRay), series.finestSpacing());
}

// A beam grid (a sonar's fan) takes one range cell in every mode, as short as the display draws any axis: its
// cells are far wider across the beams than along the range. 101 samples over ranges 2 .. 52: 0.5.
TEST(AutomaticStep, ABeamGridTakesOneRangeCell) {
    Series series;
    BeamGrid fan;
    fan.dims = {8, 6, 101};
    fan.azimuthDeg = {-30, -20, -10, 0, 10, 20, 30, 40};
    fan.elevationDeg = {-20, -10, 0, 10, 20, 30};
    fan.minRange = 2.0;
    fan.maxRange = 52.0;
    TimeStep step;
    step.grid = fan;
    series.steps.push_back(step);
    EXPECT_DOUBLE_EQ(*automaticStep(series, DisplayFrame{}, kCompositeRay), 0.5);
    EXPECT_DOUBLE_EQ(*automaticStep(series, DisplayFrame{}, *rayModeFromString("maximum")), 0.5);
    DisplayFrame flattened;
    flattened.scale = {1.0, 0.5, 1.0};
    EXPECT_DOUBLE_EQ(*automaticStep(series, flattened, kCompositeRay), 0.25);
}

}  // namespace tstyles

namespace tstyles {
namespace {

// The window's ray list (switchRayMode): on the CT phantom's automatic scene (composite), choosing
// maximum gives the STF, step and unchanged opacity `applyAutomaticRay` gives the series as read for
// maximum, exactly (the step up to rounding through the display frame); back to composite gives the
// automatic scene again. An STF the user changed stays, the step still follows.
TEST(RayModeSwitch, AChosenModeBringsItsAutomaticPartsAndLeavesTheUsersOwn) {
    const auto file = sampleFolder() / "ct-switch.nii";
    testdata::writeCtPhantom(file);
    const Series series = openSeries(file, ReadOptions{});
    const AutomaticScene automatic = automaticScene(series, file);
    ASSERT_EQ(automatic.scene.rayMode, kCompositeRay);
    const SceneOnSeries fitted = fitSceneToSeries(automatic.scene, series);
    const RayMode maximum = rayModeNamed("maximum");

    Scene expected = fitted.scene;
    applyAutomaticRay(expected, series, automaticOpacityWindow(series), maximum);
    Scene scene = fitted.scene;
    const RayModeSwitch carried = switchRayMode(scene, fitted.series, maximum);
    EXPECT_TRUE(carried.stf && carried.step && carried.unchangedOpacity);
    EXPECT_EQ(scene.rayMode, maximum);
    EXPECT_EQ(scene.stf, expected.stf);
    ASSERT_TRUE(scene.raycast.step && expected.raycast.step);
    EXPECT_NEAR(*scene.raycast.step, *expected.raycast.step, 1e-12 * *expected.raycast.step);
    EXPECT_NE(scene.raycast.step, fitted.scene.raycast.step);  // half a cell, not a whole one
    ASSERT_TRUE(scene.compositorOptions.unchanged && expected.compositorOptions.unchanged);
    EXPECT_EQ(scene.compositorOptions.unchanged->opacity, expected.compositorOptions.unchanged->opacity);

    switchRayMode(scene, fitted.series, kCompositeRay);
    EXPECT_EQ(scene.stf, fitted.scene.stf);
    EXPECT_EQ(scene.compositorOptions.unchanged, fitted.scene.compositorOptions.unchanged);

    // The user's own STF stays through a switch; the automatic step still follows the mode.
    Scene edited = fitted.scene;
    edited.stf.curve.opacity = {{0.2, 0.0}, {0.9, 0.4}};
    const RayModeSwitch kept = switchRayMode(edited, fitted.series, maximum);
    EXPECT_FALSE(kept.stf);
    EXPECT_TRUE(kept.step);
    EXPECT_EQ(edited.stf.curve.opacity, (std::vector<OpacityNode>{{0.2, 0.0}, {0.9, 0.4}}));
    EXPECT_EQ(edited.rayMode, maximum);
}

}  // namespace
}  // namespace tstyles
