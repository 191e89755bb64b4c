// Beam (sonar) grids in the raycaster, against closed-form expectations: a shell at a known range
// renders as a ring where geometry puts it, rays that leave the fan through a side or beyond the
// maximum range gather nothing there, and a box overlapping a fan is composited from both.
//
// Every test looks orthographically down -z at a fan whose transducer sits at world (0, -0.5, 0)
// with its axis along +y: grid-local x (azimuth, +-60 degrees) is world x and grid-local y
// (elevation, +-20 degrees) is world -z. A ray at world (x, y) then runs along the elevation
// direction at fixed azimuth atan2(x, Y) and ground distance rho = |(x, Y)| (Y = y + 0.5): it
// crosses the fan between the two elevation planes, a path of 2 Y tan(20 deg), at ranges from rho
// to sqrt(rho^2 + (Y tan 20)^2).
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/data/beam_geometry.h"
#include "tstyles/image/image_comparison.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 96;
constexpr double kViewHeight = 2.4;
constexpr double kPixel = kViewHeight / kSize;  // world units per pixel
const glm::dvec2 kCentre(0.0, 0.0);
const glm::dvec3 kTransducer(0.0, -0.5, 0.0);
constexpr double kAzimuthDeg = 60.0;
constexpr double kElevationDeg = 20.0;
constexpr double kMinRange = 0.1;
constexpr double kMaxRange = 1.0;
constexpr int kRangeSamples = 181;  // 0.005 apart
const double kTanElevation = std::tan(glm::radians(kElevationDeg));

BeamGrid testFan(int beamsAcross = 25, int beamsAlong = 5) {
    BeamGrid grid;
    grid.dims = {beamsAcross, beamsAlong, kRangeSamples};
    grid.azimuthDeg = evenBeamAngles(-kAzimuthDeg, kAzimuthDeg, grid.dims.x);
    grid.elevationDeg = evenBeamAngles(-kElevationDeg, kElevationDeg, grid.dims.y);
    grid.minRange = kMinRange;
    grid.maxRange = kMaxRange;
    return grid;
}

// A time-step on the test fan whose density depends on the range sample k only.
TimeStep fanStep(double time, const std::function<float(int)>& densityOfRangeSample,
                 const BeamGrid& fan = testFan()) {
    TimeStep step;
    step.time = time;
    step.grid = fan;
    step.placement.origin = kTransducer;
    // Local z (the axis) to world +y, local y to world -z: a quarter turn about -x.
    step.placement.rotation = glm::angleAxis(glm::radians(-90.0), glm::dvec3(1.0, 0.0, 0.0));
    step.rawRange = {0.0, 1.0};
    const glm::ivec3 dims = step.beam().dims;
    step.density.resize(step.beam().voxelCount());
    for (int k = 0; k < dims.z; ++k)
        std::fill_n(step.density.begin() + std::ptrdiff_t(k) * dims.x * dims.y, dims.x * dims.y,
                    densityOfRangeSample(k));
    return step;
}

Series seriesOf(std::vector<TimeStep> steps) {
    Series series;
    series.name = "beam test series";
    series.valueRange = {0.0, 1.0};
    series.steps = std::move(steps);
    return series;
}

// The world point at the centre of pixel (column, row).
glm::dvec2 pixelCentre(int column, int row) {
    return kCentre + glm::dvec2((column + 0.5) / kSize - 0.5, 0.5 - (row + 0.5) / kSize) * kViewHeight;
}

// Ground distance and azimuth (degrees) of a pixel's ray in the fan's frame.
struct FanCoordinates {
    double rho;
    double azimuthDeg;
    double axial;  // Y, the distance along the fan's axis
};
FanCoordinates fanCoordinates(glm::dvec2 world) {
    const glm::dvec2 local(world.x - kTransducer.x, world.y - kTransducer.y);
    return {glm::length(local), glm::degrees(std::atan2(local.x, local.y)), local.y};
}

double opacityOver(double opacityPerReference, double length, double referenceLength) {
    return 1.0 - std::pow(1.0 - opacityPerReference, length / referenceLength);
}

// Where a pixel's ray lies within the fan: the length between the elevation planes, cut short by
// the far cap (every ray here stays beyond the near cap).
double pathThroughFan(const FanCoordinates& ray) {
    if (ray.rho >= kMaxRange) return 0.0;
    const double halfAcross = std::min(ray.axial * kTanElevation, std::sqrt(kMaxRange * kMaxRange - ray.rho * ray.rho));
    return 2.0 * halfAcross;
}

TEST(BeamRender, ShellAtAKnownRangeRendersAsARingWhereGeometryPutsIt) {
    // Range samples within 8 of r0 = 0.7 (k = 120) hold density 1, the rest 0, so trilinear
    // interpolation crosses 0.5 at r0 +- 8.5 spacings: the shell spans [r0 - d, r0 + d].
    const double spacing = (kMaxRange - kMinRange) / (kRangeSamples - 1);
    const double r0 = kMinRange + 120 * spacing;
    const double d = 8.5 * spacing;
    const Series series = seriesOf({fanStep(0.0, [](int k) { return std::abs(k - 120) <= 8 ? 1.0f : 0.0f; })});

    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 0.0}, {0.49, 0.0}, {0.51, 1.0}};
    scene.stf.curve.color = {{0.0, {1.0, 1.0, 1.0}}};
    scene.finalMode = FinalMode::Stf;
    scene.raycast.step = 0.001;
    const Image image = renderSeries(series, scene);

    // The ray meets the shell when rho <= r0 + d and rho^2 + (Y tan 20)^2 >= (r0 - d)^2, with
    // Y = rho cos(azimuth): a ring of radius about r0 (28 pixels) around the transducer's pixel,
    // 3 to 5 pixels wide. Pixels more than one pixel inside the ring are opaque; pixels more than
    // one pixel away from it (or from the fan's sides) are empty. The pixel of tolerance covers
    // sampling along the ray where it only grazes the shell, and the 16-bit density texture.
    const double margin = 1.0 * kPixel;
    int ringPixels = 0;
    for (int row = 0; row < kSize; ++row)
        for (int column = 0; column < kSize; ++column) {
            const FanCoordinates ray = fanCoordinates(pixelCentre(column, row));
            const double cosAzimuth = std::cos(glm::radians(ray.azimuthDeg));
            const double inner = (r0 - d) / std::sqrt(1.0 + cosAzimuth * cosAzimuth * kTanElevation * kTanElevation);
            const double outer = r0 + d;
            const double alpha = image.at(column, row).a;
            const double angularMargin = glm::degrees(margin / std::max(ray.rho, 1e-9));
            const bool insideSides = std::abs(ray.azimuthDeg) <= kAzimuthDeg - angularMargin && ray.axial > 0.0;
            const bool outsideSides = std::abs(ray.azimuthDeg) >= kAzimuthDeg + angularMargin || ray.axial <= 0.0;
            if (insideSides && ray.rho >= inner + margin && ray.rho <= outer - margin) {
                EXPECT_GT(alpha, 0.99) << "ring pixel (" << column << ", " << row << ") rho " << ray.rho;
                ++ringPixels;
            } else if (outsideSides || ray.rho <= inner - margin || ray.rho >= outer + margin) {
                EXPECT_LT(alpha, 1e-3) << "pixel (" << column << ", " << row << ") rho " << ray.rho
                                       << " azimuth " << ray.azimuthDeg;
            }
        }
    // An arc of 2 x 60 degrees at radius 0.7 (29 pixels long each side), 1 to 3 pixels thick
    // where it is tested.
    EXPECT_GT(ringPixels, 80);
}

// Checks a render of a constant fan of `opacity` per `reference` length: each pixel's opacity follows
// from the length of its ray between the elevation planes and inside the far cap; beyond the
// azimuth sides and the maximum range the pixels are background although the proxy mesh's far cap
// reaches past it.
void expectConstantFanOpacities(const Image& image, double opacity, double reference, const std::string& what) {
    const double margin = 1.5 * kPixel;
    int insidePixels = 0, outsidePixels = 0;
    for (int row = 0; row < kSize; ++row)
        for (int column = 0; column < kSize; ++column) {
            const FanCoordinates ray = fanCoordinates(pixelCentre(column, row));
            const double alpha = image.at(column, row).a;
            const double angularMargin = glm::degrees(margin / std::max(ray.rho, 1e-9));
            const bool inside = ray.axial > 0.0 && std::abs(ray.azimuthDeg) <= kAzimuthDeg - angularMargin &&
                                ray.rho >= kMinRange + margin && ray.rho <= kMaxRange - margin;
            const bool outside = ray.axial <= 0.0 || std::abs(ray.azimuthDeg) >= kAzimuthDeg + angularMargin ||
                                 ray.rho >= kMaxRange + margin;
            if (inside) {
                // Densities pass through 16-bit textures and opacities through 1024-entry tables;
                // the proxy's planar sides are exact, so the path is exact up to float arithmetic.
                EXPECT_NEAR(alpha, opacityOver(opacity, pathThroughFan(ray), reference), 5e-3)
                    << what << ": pixel (" << column << ", " << row << ") rho " << ray.rho;
                ++insidePixels;
            } else if (outside) {
                EXPECT_LT(alpha, 1e-3) << what << ": pixel (" << column << ", " << row << ") outside the fan";
                ++outsidePixels;
            }
        }
    EXPECT_GT(insidePixels, 1000) << what;
    EXPECT_GT(outsidePixels, 3000) << what;
}

TEST(BeamRender, RaysGatherOnlyInsideTheFanNotBeyondItsSidesOrItsFarCap) {
    const Series series = seriesOf({fanStep(0.0, [](int) { return 1.0f; })});
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    const double opacity = 0.02;
    scene.stf.curve = constantFunction({1.0, 1.0, 1.0}, opacity);
    scene.finalMode = FinalMode::Stf;
    expectConstantFanOpacities(renderSeries(series, scene), opacity, series.finestSpacing(), "constant fan");
}

Image renderWithRaycaster(const Series& series, const Scene& scene, bool naive) {
    Renderer& renderer = testRenderer();
    renderer.setSeries(series);
    FrameOptions options;
    options.size = {scene.width, scene.height};
    options.naive = naive;
    renderer.draw(scene, resolveView(scene.camera, series.worldBounds(), scene.width, scene.height), options);
    return renderer.readFrame();
}

TEST(BeamRender, RaysOfThousandsOfSamplesGetEverySampleInBothRaycasters) {
    // Mesa's llvmpipe ends every loop of a shader invocation once 65535 loop iterations have run in
    // it in all (per 8 pixels). The beam lookup used to be a binary search over the beams, run four
    // times per time-step and sample by the optimised raycaster and twice by the naive one: with
    // 64 x 32 beams about 56 and 29 iterations per sample, so rays of more than about 1200 and 2300
    // samples stopped short and came out too faint (the sonar survey's disagreement,
    // docs/performance.md). Here the longest rays take about 2900 samples (path 0.73, step 0.00025);
    // every pixel must still match the closed form, in both raycasters.
    const Series series = seriesOf({fanStep(0.0, [](int) { return 1.0f; }, testFan(64, 32))});
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    const double opacity = 0.002;
    scene.stf.curve = constantFunction({1.0, 1.0, 1.0}, opacity);
    scene.finalMode = FinalMode::Stf;
    scene.raycast.step = 0.00025;
    const double reference = series.finestSpacing();
    expectConstantFanOpacities(renderWithRaycaster(series, scene, false), opacity, reference, "optimised");
    expectConstantFanOpacities(renderWithRaycaster(series, scene, true), opacity, reference, "naive");
}

TEST(BeamRender, BoxInsideAFanIsCompositedFromBothWhereTheyOverlap) {
    // Time-step 0 is a box 0.4 x 0.4 x 0.2 (x in [-0.2, 0.2], y in [-0.1, 0.3], z in [-0.1, 0.1])
    // that lies wholly inside the fan of time-step 1 along every ray through it. The temporal
    // average with the index TSTF alone (red, opacity 0.02 for the box; green, 0.01 for the fan)
    // gives, front to back: fan only, then both (colour (2/3, 1/3, 0), opacity 0.015), then fan only.
    BoxSpec box = constantBox({-0.2, -0.1, -0.1}, 1.0f);
    box.dims = {9, 9, 5};
    box.spacing = glm::dvec3(0.05);
    Series series = makeSeries({box});
    series.steps.push_back(fanStep(1.0, [](int) { return 1.0f; }));
    const double reference = series.finestSpacing();

    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({1.0, 1.0, 1.0}, 1.0);
    scene.compositor = compositorNamed("temporal-average");
    scene.indexTstf.curve.opacity = {{0.0, 0.02}, {1.0, 0.01}};
    scene.indexTstf.curve.color = {{0.0, {1.0, 0.0, 0.0}}, {1.0, {0.0, 1.0, 0.0}}};
    scene.finalMode = FinalMode::Tstf;
    const Image image = renderSeries(series, scene);

    const glm::dvec3 red(1.0, 0.0, 0.0), green(0.0, 1.0, 0.0);
    const double boxThickness = 0.2;
    const auto expected = [&](glm::dvec2 world, bool throughBox) {
        const double path = pathThroughFan(fanCoordinates(world));
        const double overlap = throughBox ? boxThickness : 0.0;
        const double fanOnly = opacityOver(0.01, 0.5 * (path - overlap), reference);  // each side
        const double both = opacityOver(0.015, overlap, reference);
        const glm::dvec3 bothColour = (0.02 * red + 0.01 * green) / 0.03;
        // Premultiplied front-to-back: front fan, overlap, back fan.
        const glm::dvec3 rgb = green * fanOnly + (1.0 - fanOnly) * (bothColour * both + (1.0 - both) * green * fanOnly);
        const double a = 1.0 - (1.0 - fanOnly) * (1.0 - both) * (1.0 - fanOnly);
        return glm::dvec4(rgb, a);
    };
    int checked = 0;
    for (int row = 0; row < kSize; ++row)
        for (int column = 0; column < kSize; ++column) {
            const glm::dvec2 world = pixelCentre(column, row);
            // Well inside the box's footprint, or in the fan well clear of the box.
            const bool inBox = std::abs(world.x) <= 0.2 - kPixel && world.y >= -0.1 + kPixel && world.y <= 0.3 - kPixel;
            const bool clearOfBox = std::abs(world.x) >= 0.2 + kPixel || world.y <= -0.1 - kPixel || world.y >= 0.3 + kPixel;
            const FanCoordinates ray = fanCoordinates(world);
            const bool inFan = ray.axial > 0.0 && std::abs(ray.azimuthDeg) <= 55.0 && ray.rho >= 0.15 && ray.rho <= 0.95;
            if (!inFan || (!inBox && !clearOfBox)) continue;
            const glm::dvec4 want = expected(world, inBox);
            const glm::vec4 got = image.at(column, row);
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(got[c], want[c], 5e-3) << (inBox ? "overlap" : "fan only") << " pixel (" << column
                                                   << ", " << row << ") channel " << c;
            ++checked;
        }
    EXPECT_GT(checked, 1000);
}

// Evenly spaced beams take the shader's linear angle mapping (EVEN_BEAMS), and its Jacobian for the
// neighbours of a gradient; the same fan with its inner beams nudged by 1e-6 degrees takes the
// angle list's bucket lookup and six mappings per gradient. A blob inside the fan, flat and lit-
// sphere styled, must look the same both ways: the nudge moves a beam index by 1e-7.
TEST(BeamRender, EvenlySpacedBeamsRenderAsTheAngleListDoes) {
    const BeamGrid even = testFan(25, 9);
    BeamGrid nudged = even;
    for (std::size_t i = 1; i + 1 < nudged.azimuthDeg.size(); ++i) nudged.azimuthDeg[i] += 1e-6;
    for (std::size_t j = 1; j + 1 < nudged.elevationDeg.size(); ++j) nudged.elevationDeg[j] -= 1e-6;
    ASSERT_TRUE(areEvenBeamAngles(even.azimuthDeg) && areEvenBeamAngles(even.elevationDeg));
    ASSERT_FALSE(areEvenBeamAngles(nudged.azimuthDeg) || areEvenBeamAngles(nudged.elevationDeg));

    // A Gaussian blob off the fan's axis, so that the density changes across beams, along them and
    // along the range.
    const auto blobStep = [](const BeamGrid& fan) {
        TimeStep step = fanStep(0.0, [](int) { return 0.0f; }, fan);
        const glm::dvec3 centre(0.18, -0.05, 0.6);
        for (int k = 0; k < fan.dims.z; ++k)
            for (int j = 0; j < fan.dims.y; ++j)
                for (int i = 0; i < fan.dims.x; ++i) {
                    const glm::dvec3 offset = beamSamplePosition(fan, i, j, k) - centre;
                    step.density[(std::size_t(k) * fan.dims.y + j) * fan.dims.x + i] =
                        float(std::exp(-glm::dot(offset, offset) / (0.2 * 0.2)));
                }
        return step;
    };
    for (const bool styled : {false, true}) {
        Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
        scene.stf.curve.opacity = {{0.0, 0.0}, {0.3, 0.0}, {0.8, 0.4}};
        scene.stf.curve.color = {{0.0, {1.0, 0.9, 0.8}, styled ? "glossy-orange" : "", 0}};
        scene.finalMode = FinalMode::Stf;
        scene.raycast.step = 0.004;
        const Image evenImage = renderSeries(seriesOf({blobStep(even)}), scene);
        const Image listImage = renderSeries(seriesOf({blobStep(nudged)}), scene);
        const ImageDifference difference = compareImages(evenImage, listImage, 1);
        EXPECT_LE(difference.maxDelta, 2) << (styled ? "styled: " : "flat: ") << describe(difference);
        EXPECT_EQ(difference.failingFraction, 0.0) << (styled ? "styled: " : "flat: ") << describe(difference);
        // The blob is there (a picture of background alone would pass the comparison too): it
        // covers hundreds of pixels of the transparent background.
        int covered = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) covered += evenImage.at(x, y).a > 0.1f ? 1 : 0;
        EXPECT_GT(covered, 200) << (styled ? "styled" : "flat");
    }
}

}  // namespace
}  // namespace tstyles::testing
