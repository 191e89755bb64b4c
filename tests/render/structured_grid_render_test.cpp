// Renders of explicit structured grids compared with known answers: the warped box (its mapping in
// closed form) seen down z, where the footprint follows the curved boundary and the colour follows
// the computational coordinate, and seen along its bent axis, where a ray crosses a concave gap.
#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/image/image_io.h"
#include "tstyles/data/inverse_map.h"
#include "tstyles/data/structured_point_location.h"
#include "tstyles/data/warped_box.h"

namespace tstyles::testing {
namespace {

constexpr int kSize = 64;
constexpr double kViewHeight = 1.4;
const glm::dvec2 kCentre(0.575, 0.55);
// As in the analytic tests: 16-bit densities, 1024-entry tables, float arithmetic along the ray;
// plus the inverse map's error (under 0.02 cell, i.e. 0.0013 in a density ramp of 16 cells).
constexpr float kTolerance = 3e-3f;

// The warped box with a density per node, as a one-step series at the origin.
Series warpedSeries(const WarpedBox& box, const std::function<float(glm::ivec3)>& density,
                    const glm::dquat& rotation = glm::dquat(1.0, 0.0, 0.0, 0.0)) {
    Series series;
    series.name = "warped box";
    series.valueRange = {0.0, 1.0};
    TimeStep step;
    step.grid = box.grid();
    step.placement.rotation = rotation;
    step.rawRange = {0.0, 1.0};
    for (int k = 0; k < box.dims.z; ++k)
        for (int j = 0; j < box.dims.y; ++j)
            for (int i = 0; i < box.dims.x; ++i) step.density.push_back(density({i, j, k}));
    series.steps.push_back(std::move(step));
    return series;
}

// The world (x, y) of a pixel centre of a scene made by orthographicSceneLookingDownZ.
glm::dvec2 pixelCentre(int column, int row) {
    const double pixel = kViewHeight / kSize;
    return {kCentre.x + (column + 0.5 - kSize / 2.0) * pixel, kCentre.y - (row + 0.5 - kSize / 2.0) * pixel};
}

double slabOpacity(double opacityPerReference, double thickness, double reference) {
    return 1.0 - std::pow(1.0 - opacityPerReference, thickness / reference);
}

TEST(StructuredGridRender, FootprintFollowsTheCurvedBoundaryAndColourTheComputationalCoordinate) {
    const WarpedBox box;  // z = k h: every ray down z inside the footprint crosses 0.5 of grid
    const StructuredGrid grid = box.grid();
    const StructuredPointLocator locator(grid);
    const Series series = warpedSeries(box, [&](glm::ivec3 node) { return float(node.x) / float(box.dims.x - 1); });
    Scene scene = orthographicSceneLookingDownZ(kCentre, kViewHeight, kSize);
    scene.stf.curve.opacity = {{0.0, 0.05}};
    scene.stf.curve.color = {{0.0, {0.0, 0.0, 0.0}}, {1.0, {1.0, 1.0, 1.0}}};
    scene.finalMode = FinalMode::Stf;
    const Image image = renderSeries(series, scene);

    const double alpha = slabOpacity(0.05, 0.5, series.finestSpacing());
    const double margin = 1.5 * kViewHeight / kSize;  // pixels this close to the boundary are skipped
    int inside = 0, outsideInBounds = 0;
    for (int row = 0; row < kSize; ++row)
        for (int column = 0; column < kSize; ++column) {
            const glm::dvec2 world = pixelCentre(column, row);
            ASSERT_EQ(pixelOf(world, kCentre, kViewHeight, kSize), glm::ivec2(column, row));
            const auto at = [&](glm::dvec2 offset) { return locator.locate({world + offset, 0.25}); };
            const auto exact = at({0.0, 0.0});
            bool clear = true;
            for (const glm::dvec2 offset : {glm::dvec2(margin, 0), glm::dvec2(-margin, 0), glm::dvec2(0, margin),
                                            glm::dvec2(0, -margin)})
                clear = clear && bool(at(offset)) == bool(exact);
            if (!clear) continue;
            const glm::vec4 actual = image.at(column, row);
            glm::vec4 expected(0.0f);
            if (exact) {
                ++inside;
                const double density = exact->x / (box.dims.x - 1);
                expected = glm::vec4(glm::vec3(float(density * alpha)), float(alpha));
            } else if (world.x > grid.localLower.x && world.x < grid.localUpper.x && world.y > grid.localLower.y &&
                       world.y < grid.localUpper.y) {
                ++outsideInBounds;  // inside the bounding box but outside the grid: must stay empty
            }
            for (int c = 0; c < 4; ++c)
                ASSERT_NEAR(actual[c], expected[c], kTolerance)
                    << "pixel (" << column << ", " << row << ") at world (" << world.x << ", " << world.y
                    << ") channel " << c << (exact ? " inside" : " outside");
        }
    EXPECT_GT(inside, 1500);
    EXPECT_GT(outsideInBounds, 100);
}

TEST(StructuredGridRender, ALeftHandedGridGetsTheSameSlab) {
    // Mirrored in x, every cell is left-handed: the boundary normals must still point outwards, or
    // entries and exits swap and the slab vanishes.
    const WarpedBox box;
    std::vector<glm::vec3> nodes = *box.grid().nodes;
    for (glm::vec3& node : nodes) node.x = -node.x;
    Series series = warpedSeries(box, [](glm::ivec3) { return 1.0f; });
    series.steps[0].grid = makeStructuredGrid(box.dims, nodes);
    const glm::dvec2 centre(-0.575, 0.55);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({1.0, 1.0, 1.0}, 0.05);
    scene.finalMode = FinalMode::Stf;
    const Image image = renderSeries(series, scene);
    const double alpha = slabOpacity(0.05, 0.5, series.finestSpacing());
    for (const glm::dvec2 world : {glm::dvec2(-0.575, 0.55), glm::dvec2(-0.9, 0.2), glm::dvec2(-0.4, 0.9)}) {
        const glm::ivec2 pixel = pixelOf(world, centre, kViewHeight, kSize);
        EXPECT_NEAR(image.at(pixel.x, pixel.y).a, alpha, kTolerance) << world.x << ", " << world.y;
    }
    const glm::ivec2 outside = pixelOf({-0.05, 0.55}, centre, kViewHeight, kSize);  // beyond the bent face
    EXPECT_NEAR(image.at(outside.x, outside.y).a, 0.0f, kTolerance);
}

TEST(StructuredGridRender, RaysThroughAConcaveGapSkipIt) {
    // Rotated +90 degrees about x, local y becomes world z: rays down z run along local y. At
    // local x = 0.1 the bent -x face (x = 0.15 sin(pi y / 1.0)) leaves the ray inside the grid for
    // y < 0.23 and y > 0.77 only: two intervals with a gap between them.
    const WarpedBox box;
    const StructuredGrid grid = box.grid();
    const StructuredPointLocator locator(grid);
    const glm::dquat rotation = glm::angleAxis(glm::radians(90.0), glm::dvec3(1.0, 0.0, 0.0));
    const Series series = warpedSeries(box, [](glm::ivec3) { return 1.0f; }, rotation);
    const glm::dvec2 centre(0.575, -0.25);
    Scene scene = orthographicSceneLookingDownZ(centre, kViewHeight, kSize);
    scene.stf.curve = constantFunction({1.0, 1.0, 1.0}, 0.02);
    scene.finalMode = FinalMode::Stf;
    const Image image = renderSeries(series, scene);

    const double reference = series.finestSpacing();
    const double texel = (grid.localUpper.y - grid.localLower.y) / (inverseMapDims(grid).y - 1);
    for (const double localX : {0.05, 0.1, 0.5}) {
        const glm::dvec2 world(localX, -0.25);  // local z = 0.25
        // The length of the ray inside the grid, by exact point location every 1e-4.
        double length = 0.0;
        int pieces = 0;
        bool wasInside = false;
        for (double y = 0.0; y <= grid.localUpper.y; y += 1e-4) {
            const bool isInside = bool(locator.locate({localX, y, 0.25}));
            if (isInside) length += 1e-4;
            if (isInside && !wasInside) ++pieces;
            wasInside = isInside;
        }
        const glm::ivec2 pixel = pixelOf(world, centre, kViewHeight, kSize);
        const float actual = image.at(pixel.x, pixel.y).a;
        // Where the ray has a gap, the inverse map may count up to one texel on either side of it
        // as inside, and each sample stands for a whole ray step (half the reference length); the
        // gap itself (about 0.5) must not count.
        const double slack = pieces > 1 ? 2.0 * (texel + 0.5 * reference) : 0.0;
        EXPECT_GE(actual, slabOpacity(0.02, length, reference) - kTolerance) << "x = " << localX;
        EXPECT_LE(actual, slabOpacity(0.02, length + slack, reference) + kTolerance) << "x = " << localX;
        if (localX == 0.1) {
            EXPECT_EQ(pieces, 2);
            EXPECT_LT(actual, slabOpacity(0.02, grid.localUpper.y - 0.3, reference));
        }
    }
}

// A style whose colour is the normal it is looked up at: red = 0.5 + 0.5 nx, green = 0.5 + 0.5 ny.
std::string writeNormalStyle() {
    constexpr int kStyleSize = 64;
    Image image(kStyleSize, kStyleSize);
    for (int row = 0; row < kStyleSize; ++row)
        for (int column = 0; column < kStyleSize; ++column) {
            const glm::vec2 normal((column + 0.5f) / kStyleSize * 2.0f - 1.0f, 1.0f - (row + 0.5f) / kStyleSize * 2.0f);
            image.set(column, row, glm::vec4(0.5f + 0.5f * normal.x, 0.5f + 0.5f * normal.y, 0.0f, 1.0f));
        }
    const auto file = std::filesystem::temp_directory_path() /
                      ("tstyles_structured_normal_style_" + std::to_string(::getpid()) + ".png");
    writeImage(image, file);
    return file.string();
}

TEST(StructuredGridRender, LitSphereStylesSeeWorldSpaceNormalsOnABentGrid) {
    // A ball defined in world space, sampled at the nodes of a bent grid: its surface normals are
    // radial whatever the grid, so the style shows the sphere's normal at each pixel. Gradients taken
    // in the grid's computational space would skew them by the bend: with them this test fails
    // by up to 0.12 in colour (checked by swapping structured_gradient.glsl for voxel differences).
    WarpedBox box;
    box.dims = {33, 33, 33};
    box.spacing = 1.0 / 32.0;
    box.amplitude = {0.25, 0.2, 0.15};
    const glm::dvec3 centre(0.65, 0.55, 0.5);
    constexpr double kRadius = 0.3;
    const StructuredGrid grid = box.grid();
    const Series series = warpedSeries(box, [&](glm::ivec3 node) {
        const double r = glm::length(grid.node(node.x, node.y, node.z) - centre);
        return float(std::clamp((kRadius - r) / (2.0 / 32.0) + 0.5, 0.0, 1.0));
    });
    Scene scene = orthographicSceneLookingDownZ({centre.x, centre.y}, 1.0, kSize);
    scene.stf.curve.opacity = {{0.45, 0.0}, {0.55, 1.0}};
    scene.stf.curve.color = {{0.0, {1.0, 1.0, 1.0}, writeNormalStyle(), 0}};
    scene.finalMode = FinalMode::Stf;
    const Image image = renderSeries(series, scene);
    for (const glm::dvec2 offset : {glm::dvec2(0.0, 0.0), glm::dvec2(-0.2, 0.0), glm::dvec2(0.2, 0.05),
                                    glm::dvec2(0.0, 0.2), glm::dvec2(-0.12, -0.15), glm::dvec2(0.15, 0.15)}) {
        const glm::ivec2 pixel = pixelOf(glm::dvec2(centre) + offset, {centre.x, centre.y}, 1.0, kSize);
        const glm::vec4 actual = image.at(pixel.x, pixel.y);
        const glm::dvec2 normal = offset / kRadius;
        // 0.05 in colour is 0.1 in the normal's x or y: the surface of a trilinear field between
        // nodes is not quite a sphere, and 8-bit style texels add a little.
        EXPECT_NEAR(actual.r, 0.5 + 0.5 * normal.x, 0.05) << "offset " << offset.x << ", " << offset.y;
        EXPECT_NEAR(actual.g, 0.5 + 0.5 * normal.y, 0.05) << "offset " << offset.x << ", " << offset.y;
        EXPECT_NEAR(actual.a, 1.0, kTolerance);
    }
}

}  // namespace
}  // namespace tstyles::testing
