// The picture moved beside the panels (src/annotate/picture_room.h) in closed form, and on every
// layout case: no panel, legend or scale bar meets the data's footprint on the image.
#include <gtest/gtest.h>

#include "../../src/annotate/box_projection.h"
#include "../../src/annotate/picture_room.h"
#include "layout_cases.h"

namespace tstyles::testing {
namespace {

bool overlap(const Rect& a, const Rect& b) {
    return std::min(a.right(), b.right()) > std::max(a.x, b.x) && std::min(a.bottom(), b.bottom()) > std::max(a.y, b.y);
}

TEST(PictureRoom, AFootprintClearOfThePanelsStaysWhereItIs) {
    const PictureMove move = moveClearOf({100, 100, 200, 150}, {640, 480}, {{400, 10, 200, 100}}, 5.0);
    EXPECT_TRUE(move.isIdentity());
}

TEST(PictureRoom, APanelOverThePictureMovesItBesideThePanelAtItsSizeWhereThereIsRoom) {
    // A 300x200 picture at x 300..600 under a legend from x 440 on: the room left of the legend
    // (gap 10) is x 10..430, so the picture keeps its size and moves left only until it ends 10
    // pixels before the legend.
    const Rect footprint{300, 140, 300, 200};
    const PictureMove move = moveClearOf(footprint, {640, 480}, {{440, 10, 190, 400}}, 10.0);
    EXPECT_DOUBLE_EQ(move.scale, 1.0);
    const Rect moved = move.apply(footprint);
    EXPECT_DOUBLE_EQ(moved.right(), 430.0);
    EXPECT_DOUBLE_EQ(moved.y, 140.0);  // nearest to where it was: not moved vertically
    EXPECT_DOUBLE_EQ(moved.width, 300.0);
}

TEST(PictureRoom, APictureWiderThanTheRoomShrinksToTheRoomsWidth) {
    // The whole width under a legend on the right third: the room is 10..420 (gap 10), 410 wide,
    // and the 620-pixel picture shrinks to 410 / 620 of its size.
    const Rect footprint{10, 100, 620, 300};
    const PictureMove move = moveClearOf(footprint, {640, 480}, {{430, 0, 210, 480}}, 10.0);
    EXPECT_NEAR(move.scale, 410.0 / 620.0, 1e-12);
    const Rect moved = move.apply(footprint);
    EXPECT_GE(moved.x, 10.0 - 1e-9);
    EXPECT_LE(moved.right(), 420.0 + 1e-9);
}

TEST(PictureRoom, NoRoomAtAllGivesScaleZero) {
    const PictureMove move = moveClearOf({0, 0, 640, 480}, {640, 480}, {{0, 0, 640, 480}}, 2.0);
    EXPECT_EQ(move.scale, 0.0);
}

TEST(PictureRoom, TheMovedViewProjectsEveryPointWhereTheMoveSendsIt) {
    // Perspective and orthographic: the projection followed by the move in device coordinates is
    // the move of the projected point, exactly (to rounding).
    for (const Projection projection : {Projection::Perspective, Projection::Orthographic}) {
        Camera camera;
        camera.projection = projection;
        camera.pose = OrbitCamera{std::nullopt, std::nullopt, 30.0, 20.0};
        const Bounds bounds{{-1.0, -0.5, -2.0}, {1.0, 0.5, 2.0}};
        const glm::ivec2 size{640, 480};
        const View view = resolveView(camera, bounds, size.x, size.y);
        const PictureMove move{0.6, {320.0, 240.0}, {200.0, 300.0}};
        const View moved = movedOnImage(view, size, move);
        for (int bits = 0; bits < 8; ++bits) {
            const glm::dvec3 corner = boxCorner(bounds, bits);
            const glm::dvec2 before = *projectToImage(view, size, corner);
            const glm::dvec2 after = *projectToImage(moved, size, corner);
            const glm::dvec2 expected = move.to + move.scale * (before - move.from);
            EXPECT_NEAR(after.x, expected.x, 1e-9);
            EXPECT_NEAR(after.y, expected.y, 1e-9);
        }
    }
}

TEST(PictureRoom, OnEveryLayoutCaseNoPanelMeetsTheDataAndThePictureKeepsHalfItsSize) {
    // The rectangles of the title, caption, legends and scale bar against the footprint of the
    // framed bounds under the plan's view; the footprint at least half as wide as the camera's
    // part of it on the image.
    const Font font = Font::openDefault();
    int moved = 0;
    for (const LayoutCase& layoutCase : layoutCases())
        for (const glm::ivec2 size : layoutImageSizes()) {
            SCOPED_TRACE(layoutCase.name + " at " + std::to_string(size.x) + "x" + std::to_string(size.y));
            const auto sized = planAt(layoutCase, size, font);
            const auto before = footprintOnImage(sized->view, size, layoutCase.fitted.framed);
            const auto after = footprintOnImage(sized->plan.view, size, layoutCase.fitted.framed);
            ASSERT_TRUE(before && after);
            const double shownWidth = std::min(before->right(), double(size.x)) - std::max(before->x, 0.0);
            EXPECT_GE(after->width, 0.5 * shownWidth - 1e-6);
            if (after->width < before->width - 1e-6 || after->x != before->x || after->y != before->y) ++moved;
            for (const PlacedAnnotation& element : sized->plan.layout.elements) {
                const bool panel = element.kind != AnnotationKind::TickLabel && element.kind != AnnotationKind::AxisTitle;
                if (panel) {
                    EXPECT_FALSE(overlap(element.rect, *after))
                        << toString(element.kind) << " \"" << element.text << "\" at " << element.rect.x << ","
                        << element.rect.y << " meets the picture " << after->x << "," << after->y << " "
                        << after->width << "x" << after->height;
                }
            }
        }
    // The global ocean and the maps under their legends move; most of the rest have room already.
    EXPECT_GT(moved, 0);
}

}  // namespace
}  // namespace tstyles::testing
