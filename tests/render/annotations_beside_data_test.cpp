// Annotations never cover the data, by the pixels: each layout case (tests/annotate/layout_cases.h:
// the bundled scenes, the realistic files, synthetic series shaped like users' own) is planned with
// every annotation on, as `render --annotate` plans it, and rendered without annotations through the
// plan's view on a transparent background; every pixel under every placed element (title, caption,
// legends, scale bar, axis titles, tick labels) must then be background, alpha 0. The box's edges and
// the coast are part of the picture and not checked. One backend (EGL): the layout is the same
// under either context.
#include <algorithm>
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "../annotate/layout_cases.h"
#include "render_test_support.h"

namespace tstyles::testing {
namespace {

struct Covered {
    int pixels = 0;       // pixels under the element that hold data
    float largest = 0.0f;  // the largest alpha among them
    glm::ivec2 first{-1};
};

Covered dataUnder(const Image& plain, const Rect& rect) {
    Covered covered;
    const int x0 = std::max(0, int(std::floor(rect.x))), y0 = std::max(0, int(std::floor(rect.y)));
    const int x1 = std::min(plain.width, int(std::ceil(rect.right())));
    const int y1 = std::min(plain.height, int(std::ceil(rect.bottom())));
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const float alpha = plain.at(x, y).a;
            if (alpha <= 0.0f) continue;
            if (covered.pixels++ == 0) covered.first = {x, y};
            covered.largest = std::max(covered.largest, alpha);
        }
    return covered;
}

void expectElementsOnBackground(const LayoutCase& layoutCase, glm::ivec2 size, const Font& font) {
    SCOPED_TRACE(layoutCase.name + " at " + std::to_string(size.x) + "x" + std::to_string(size.y));
    const auto sized = planAt(layoutCase, size, font);
    Scene plain = sized->scene;
    plain.annotations = Annotations{};
    plain.background = glm::dvec4(0.0);
    FrameOptions options;
    options.size = size;
    Renderer& renderer = testRenderer();
    renderer.draw(plain, sized->plan.view, options);
    const Image image = renderer.readFrame();
    ASSERT_EQ(image.width, size.x);
    for (const PlacedAnnotation& element : sized->plan.layout.elements) {
        const Covered covered = dataUnder(image, element.rect);
        EXPECT_EQ(covered.pixels, 0) << toString(element.kind) << " \"" << element.text << "\" at " << element.rect.x
                                     << "," << element.rect.y << " lies over " << covered.pixels
                                     << " pixels of data (first at " << covered.first.x << "," << covered.first.y
                                     << ", alpha up to " << covered.largest << ")";
    }
}

TEST(AnnotationsBesideData, NoElementLiesOverDataOnAnyLayoutCaseAtAnySize) {
    // Every case at every size, but the bundled scenes at 1920x1080, whose full-size renders would
    // take most of a minute: their layout is checked by rectangles at that size
    // (PictureRoom.OnEveryLayoutCaseNoPanelMeetsTheDataAndThePictureKeepsHalfItsSize).
    const Font font = Font::openDefault();
    ASSERT_GE(layoutCases().size(), 30u);
    for (const LayoutCase& layoutCase : layoutCases()) {
        testRenderer().setSeries(layoutCase.fitted.series);
        for (const glm::ivec2 size : layoutImageSizes())
            if (!layoutCase.bundled || size.x * size.y <= 640 * 480) expectElementsOnBackground(layoutCase, size, font);
    }
}

}  // namespace
}  // namespace tstyles::testing
