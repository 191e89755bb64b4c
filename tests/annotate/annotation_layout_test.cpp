// The layout by rectangles: on every bundled scene, the realistic files and synthetic series like
// users' own, with every annotation on, at 320x240, 640x480 and 1920x1080, no two placed elements
// overlap and none leaves the image; long names are shortened, crowded tick labels thinned.
#include <sstream>

#include <gtest/gtest.h>

#include "layout_cases.h"
#include "tstyles/annotate/scene_annotations.h"

namespace tstyles::testing {
namespace {

bool overlap(const Rect& a, const Rect& b) {
    return std::min(a.right(), b.right()) > std::max(a.x, b.x) && std::min(a.bottom(), b.bottom()) > std::max(a.y, b.y);
}

std::string describe(const PlacedAnnotation& element) {
    std::ostringstream text;
    text << toString(element.kind) << " \"" << element.text << "\" at " << element.rect.x << "," << element.rect.y
         << " " << element.rect.width << "x" << element.rect.height;
    return text.str();
}

std::string describe(const AnnotationLayout& layout) {
    std::string text;
    for (const PlacedAnnotation& element : layout.elements) text += "  " + describe(element) + "\n";
    return text;
}

int countOf(const AnnotationLayout& layout, AnnotationKind kind) {
    return int(std::count_if(layout.elements.begin(), layout.elements.end(),
                             [kind](const PlacedAnnotation& element) { return element.kind == kind; }));
}

TEST(AnnotationLayout, NoTwoElementsOverlapAndNoneLeavesTheImage) {
    const Font font = Font::openDefault();
    ASSERT_GE(layoutCases().size(), 30u) << "20 bundled scenes, 4 realistic files, 3 synthetic series seen two "
                                            "ways";
    for (const LayoutCase& layoutCase : layoutCases())
        for (const glm::ivec2 size : layoutImageSizes()) {
            const auto sized = planAt(layoutCase, size, font);
            const AnnotationLayout& layout = sized->plan.layout;
            SCOPED_TRACE(layoutCase.name + " at " + std::to_string(size.x) + "x" + std::to_string(size.y) + "\n" +
                         describe(layout));
            ASSERT_EQ(layout.elements.size(), sized->plan.drawElements.size());
            for (std::size_t i = 0; i < layout.elements.size(); ++i) {
                const Rect& rect = layout.elements[i].rect;
                EXPECT_GE(rect.x, 0.0) << describe(layout.elements[i]);
                EXPECT_GE(rect.y, 0.0) << describe(layout.elements[i]);
                EXPECT_LE(rect.right(), size.x) << describe(layout.elements[i]);
                EXPECT_LE(rect.bottom(), size.y) << describe(layout.elements[i]);
                EXPECT_GT(rect.width * rect.height, 0.0) << describe(layout.elements[i]);
                for (std::size_t j = i + 1; j < layout.elements.size(); ++j)
                    EXPECT_FALSE(overlap(rect, layout.elements[j].rect))
                        << describe(layout.elements[i]) << " overlaps " << describe(layout.elements[j]);
            }
            // What gives way is the box's labels and the scale bar, never the title, caption or the
            // first legend.
            EXPECT_EQ(countOf(layout, AnnotationKind::Title), 1);
            EXPECT_EQ(countOf(layout, AnnotationKind::Caption), 1);
            EXPECT_GE(countOf(layout, AnnotationKind::Legend), 1);
        }
}

TEST(AnnotationLayout, ALargeImageShowsEveryKindOfElement) {
    // At 1920x1080 there is room for all of it on the files users bring: labelled ticks with their
    // axis titles and the scale bar with its label.
    const Font font = Font::openDefault();
    for (const LayoutCase& layoutCase : layoutCases()) {
        if (layoutCase.name.find(".n") == std::string::npos) continue;  // the realistic and synthetic files
        const auto sized = planAt(layoutCase, {1920, 1080}, font);
        const AnnotationLayout& layout = sized->plan.layout;
        SCOPED_TRACE(layoutCase.name + "\n" + describe(layout));
        EXPECT_EQ(countOf(layout, AnnotationKind::ScaleBar), 1);
        EXPECT_EQ(countOf(layout, AnnotationKind::ScaleBarLabel), 1);
        EXPECT_GE(countOf(layout, AnnotationKind::AxisTitle), 2);
        EXPECT_GE(countOf(layout, AnnotationKind::TickLabel), 4);
    }
}

TEST(AnnotationLayout, ALongTitleIsShortenedWithAnEllipsisToFitBesideTheLegend) {
    const Font font = Font::openDefault();
    const LayoutCase& ocean = *std::find_if(layoutCases().begin(), layoutCases().end(), [](const LayoutCase& c) {
        return c.name == "synthetic-sea_water_potential_temperature.nc";
    });
    LayoutCase longTitle = ocean;
    longTitle.fitted.scene.annotations.title =
        "Sea water potential temperature of the global ocean, monthly means from "
        "the reanalysis, 1970";
    const auto sized = planAt(longTitle, {320, 240}, font);
    const AnnotationLayout& layout = sized->plan.layout;
    SCOPED_TRACE(describe(layout));
    const auto title = std::find_if(layout.elements.begin(), layout.elements.end(),
                                    [](const PlacedAnnotation& e) { return e.kind == AnnotationKind::Title; });
    ASSERT_NE(title, layout.elements.end());
    EXPECT_EQ(title->text.substr(title->text.size() - 3), "\u2026");
    EXPECT_EQ(title->text.rfind("Sea water potential", 0), 0u);
    EXPECT_LE(title->rect.right(), 320.0);
}

TEST(AnnotationLayout, TickLabelsStandOnTheBoxEdgesFacingTheViewer) {
    // The ocean map seen from the south and above, in perspective (the automatic camera, straight
    // above and orthographic, sees no face but the top, whose edges all face it): the longitude
    // labels on the front (southern) bottom edge, below the middle of the box in the picture.
    const Font font = Font::openDefault();
    LayoutCase ocean = *std::find_if(layoutCases().begin(), layoutCases().end(), [](const LayoutCase& c) {
        return c.name == "synthetic-sea_water_potential_temperature.nc";
    });
    ocean.fitted.scene.camera.pose = OrbitCamera{.azimuthDeg = 0.0, .elevationDeg = 50.0};
    ocean.fitted.scene.camera.projection = Projection::Perspective;
    const auto sized = planAt(ocean, {1920, 1080}, font);
    const AnnotationLayout& layout = sized->plan.layout;
    SCOPED_TRACE(describe(layout));
    int longitudes = 0;
    for (const PlacedAnnotation& element : layout.elements)
        if (element.kind == AnnotationKind::TickLabel && (element.text == "-100" || element.text == "100")) {
            EXPECT_GT(element.rect.y, 540.0) << describe(element);
            ++longitudes;
        }
    EXPECT_GE(longitudes, 1);
}

}  // namespace
}  // namespace tstyles::testing
