// The display frame: orientation from the file's axis meaning, the aspect rules, and the series
// turned and scaled into it (closed-form expectations).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/data/display_frame.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles {
namespace {

// One time-step on a box grid: `extent` world units along x, y, z from `origin`.
Series boxSeries(glm::dvec3 origin, glm::dvec3 extent, std::array<SpatialAxis, 3> axes) {
    Series series;
    series.manifestPath = "box.nc";
    RectilinearGrid grid;
    grid.dims = {5, 5, 5};
    grid.spacing = extent / 4.0;
    TimeStep step;
    step.grid = grid;
    step.placement.origin = origin;
    step.density.assign(125, 0.5f);
    series.steps.push_back(step);
    series.axes = axes;
    return series;
}

// lon 20 degrees from -40, lat 15 from 30, depth 1000 m negated by the reader (z = -1000 .. 0).
Series geographicBox() {
    return boxSeries({-40.0, 30.0, -1000.0}, {20.0, 15.0, 1000.0},
                     {SpatialAxis{"lon", "degrees_east", AxisDirection::East},
                      SpatialAxis{"lat", "degrees_north", AxisDirection::North},
                      SpatialAxis{"depth", "m", AxisDirection::Up}});
}

DisplaySettings automatic() {
    DisplaySettings settings;
    settings.orientation.mode = Orientation::Mode::Auto;
    settings.aspect.mode = Aspect::Mode::Auto;
    settings.verticalExaggeration.reset();
    return settings;
}

TEST(DisplayFrame, GeographicDataIsEastRightUpUpNorthAway) {
    const DisplayFrame frame = chooseDisplayFrame(automatic(), geographicBox());
    EXPECT_EQ(frame.rotation * glm::dvec3(1, 0, 0), glm::dvec3(1, 0, 0));   // east -> right
    EXPECT_EQ(frame.rotation * glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0));   // up -> up
    EXPECT_EQ(frame.rotation * glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1));  // north -> away from the camera
    EXPECT_DOUBLE_EQ(glm::determinant(frame.rotation), 1.0);
}

TEST(DisplayFrame, MixedUnitsMakeAMapWithCosLatitudeAndAQuarterHeight) {
    const DisplayFrame frame = chooseDisplayFrame(automatic(), geographicBox());
    const double cosLatitude = std::cos(37.5 * std::numbers::pi / 180.0);
    EXPECT_NEAR(frame.scale.x, cosLatitude, 1e-12);
    EXPECT_DOUBLE_EQ(frame.scale.z, 1.0);
    // Width = 20 cos(37.5 deg) = 15.87 degrees of latitude; 1000 m is 1000 / 111320 of them. The
    // exaggeration (rounded to two digits) makes the height about a quarter of the width.
    const double width = 20.0 * cosLatitude;
    const double height = 1000.0 * frame.scale.y;
    EXPECT_NEAR(height / width, 0.25, 0.25 * 0.05);
    EXPECT_NEAR(frame.verticalExaggeration, 440.0, 1e-9);  // 0.25 * 15.87 / (1000 / 111320) = 441.6
}

TEST(DisplayFrame, AnatomicalDataFacesTheViewerHeadUp) {
    const Series head = boxSeries({0, 0, 0}, {180, 220, 200},
                                  {SpatialAxis{"x", "mm", AxisDirection::Right},
                                   SpatialAxis{"y", "mm", AxisDirection::Anterior},
                                   SpatialAxis{"z", "mm", AxisDirection::Superior}});
    const DisplayFrame frame = chooseDisplayFrame(automatic(), head);
    EXPECT_EQ(frame.rotation * glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0));  // the patient's right on the image's left
    EXPECT_EQ(frame.rotation * glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1));   // anterior toward the camera
    EXPECT_EQ(frame.rotation * glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0));   // superior up
    EXPECT_EQ(frame.scale, glm::dvec3(1.0));  // all in mm, at most 1.2 times each other: physical
}

TEST(DisplayFrame, LengthsInDifferentUnitsArePhysicalInMetres) {
    const Series series = boxSeries({0, 0, 0}, {2, 3, 1000},
                                    {SpatialAxis{"x", "km", AxisDirection::Unknown},
                                     SpatialAxis{"y", "km", AxisDirection::Unknown},
                                     SpatialAxis{"z", "m", AxisDirection::Unknown}});
    const DisplayFrame frame = chooseDisplayFrame(automatic(), series);
    EXPECT_EQ(frame.rotation, glm::dmat3(1.0));
    EXPECT_EQ(frame.scale, glm::dvec3(1000.0, 1000.0, 1.0));
}

TEST(DisplayFrame, CubicStretchesEveryAxisToTheLongest) {
    DisplaySettings settings;
    settings.aspect.mode = Aspect::Mode::Cubic;
    const DisplayFrame frame = chooseDisplayFrame(settings, boxSeries({0, 0, 0}, {2, 4, 8}, {}));
    EXPECT_EQ(frame.scale, glm::dvec3(4.0, 2.0, 1.0));
}

TEST(DisplayFrame, AppliedSeriesHasTheTurnedAndScaledBounds) {
    const Series raw = geographicBox();
    const DisplayFrame frame = chooseDisplayFrame(automatic(), raw);
    const Series shown = applyDisplayFrame(raw, frame);
    const Bounds bounds = shown.worldBounds();
    const glm::dvec3 a = frame.toDisplay(raw.worldBounds().lower);
    const glm::dvec3 b = frame.toDisplay(raw.worldBounds().upper);
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(bounds.lower[axis], std::min(a[axis], b[axis]), 1e-9);
        EXPECT_NEAR(bounds.upper[axis], std::max(a[axis], b[axis]), 1e-9);
    }
    EXPECT_EQ(shown.axes[1].name, "depth");
    EXPECT_EQ(shown.axes[2].direction, AxisDirection::South);  // display z is the negated latitude
}

TEST(DisplayFrame, AShownPlaceIsInTheFileCoordinatesAndBack) {
    // The depth axis counts down in the file (negated by the reader): 250 m deep is world z = -250,
    // shown up the display's y axis, exaggerated. The place 30 east, 40 north, 250 m deep:
    Series raw = geographicBox();
    raw.axes[2].negated = true;
    const DisplayFrame frame = chooseDisplayFrame(automatic(), raw);
    const Series shown = applyDisplayFrame(raw, frame);
    const glm::dvec3 file{-30.0, 40.0, 250.0};
    const glm::dvec3 display = frame.toDisplay(worldCoordinatesOf(raw, file));
    EXPECT_NEAR(display.y, -250.0 * frame.scale.y, 1e-9);
    const glm::dvec3 back = fileCoordinatesOfShown(shown, frame, display);
    for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(back[axis], file[axis], 1e-9) << "axis " << axis;
    const glm::dvec3 again = shownCoordinatesOfFile(shown, frame, file);
    for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(again[axis], display[axis], 1e-9) << "axis " << axis;
    EXPECT_EQ(frame.toWorld(frame.toDisplay(glm::dvec3(1.0, 2.0, 3.0))), glm::dvec3(1.0, 2.0, 3.0));
}

TEST(DisplayFrame, TheDefaultLeavesTheSeriesAsItIs) {
    const Series raw = geographicBox();
    const DisplayFrame frame = chooseDisplayFrame(DisplaySettings{}, raw);
    EXPECT_TRUE(frame.isIdentity());
    EXPECT_EQ(applyDisplayFrame(raw, frame).steps[0].placement, raw.steps[0].placement);
}

TEST(DisplayFrame, AScaleThatWouldShearARotatedGridIsRefused) {
    Series raw = boxSeries({0, 0, 0}, {1, 1, 1}, {});
    raw.steps[0].placement.rotation = fromAxisAngle({{0, 0, 1}, 30.0});
    DisplaySettings settings;
    settings.aspect.mode = Aspect::Mode::Scale;
    settings.aspect.scale = {1.0, 2.0, 1.0};
    try {
        applyDisplayFrame(raw, chooseDisplayFrame(settings, raw));
        FAIL() << "expected an InputError";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("time-step 0 of box.nc"), std::string::npos) << error.what();
    }
}

TEST(DisplaySceneKeys, RoundTripAndErrors) {
    const Scene scene = parseScene(R"({"dataset": "d.nc", "orientation": ["+x", "+z", "-y"], "aspect": [1, 2, 3],
        "vertical_exaggeration": "auto", "camera": {"frame": "visible"}, "tstf": {"gradient": {"range": "auto"}}})",
                                   "s.json");
    EXPECT_EQ(scene.display.orientation.mode, Orientation::Mode::Axes);
    EXPECT_EQ(scene.display.orientation.axes[2], (SignedAxis{1, true}));
    EXPECT_EQ(scene.display.aspect.scale, glm::dvec3(1, 2, 3));
    EXPECT_FALSE(scene.display.verticalExaggeration.has_value());
    EXPECT_EQ(scene.camera.framing, Framing::Visible);
    EXPECT_TRUE(scene.gradientTstf.automaticRange);
    EXPECT_EQ(parseScene(sceneToJson(scene, ""), ""), scene);

    auto message = [](const std::string& json) {
        try {
            parseScene(json, "s.json");
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(R"({"dataset": "d", "orientation": ["+x", "+y", "-z"]})"),
              "s.json: orientation: mirrors the data (a left-handed frame); negate one axis");
    EXPECT_EQ(message(R"({"dataset": "d", "orientation": ["+x", "+x", "+z"]})"), "s.json: orientation: names an axis twice");
    EXPECT_NE(message(R"({"dataset": "d", "aspect": "squashed"})").find("s.json: aspect: unknown value \"squashed\""),
              std::string::npos);
    EXPECT_NE(message(R"({"dataset": "d", "vertical_exaggeration": 0})").find("s.json: vertical_exaggeration"),
              std::string::npos);
}

}  // namespace
}  // namespace tstyles
