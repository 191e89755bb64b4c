// The layout by the pixels drawn: each placed element drawn alone into a blank image, on every
// layout case at every size. Any coverage counts as ink (alpha > 0, anti-aliased edges included);
// no pixel may be inked by two elements, each element's ink lies inside its reported rectangle, and
// a tick label's or axis title's ink keeps one clear pixel from any other element's ink.
//
// The one-pixel clearance is what the layout promises for text (TextBox holds the glyphs' ink with
// a spare pixel on each side), so that neighbouring texts never touch; panels may touch each other
// (the scale bar and its label are one ground in two parts), so it is not asked of them.
#include <gtest/gtest.h>

#include "layout_cases.h"
#include "tstyles/annotate/scene_annotations.h"

namespace tstyles::testing {
namespace {

constexpr int kNobody = -1;
constexpr int kSeveral = -2;

bool isText(AnnotationKind kind) { return kind == AnnotationKind::TickLabel || kind == AnnotationKind::AxisTitle; }

// Per pixel, which element inked it (kNobody, an element's index, or kSeveral).
struct InkOwners {
    glm::ivec2 size;
    std::vector<int> owner;
    int at(int x, int y) const { return owner[std::size_t(y) * std::size_t(size.x) + std::size_t(x)]; }
};

InkOwners drawEachAlone(const AnnotationPlan& plan, glm::ivec2 size) {
    InkOwners owners{size, std::vector<int>(std::size_t(size.x) * std::size_t(size.y), kNobody)};
    Image blank(size.x, size.y);
    const AnnotationLayout& layout = plan.layout;
    for (std::size_t index = 0; index < layout.elements.size(); ++index) {
        std::fill(blank.rgba.begin(), blank.rgba.end(), 0.0f);
        Canvas canvas(blank);
        plan.drawElements[index](canvas);
        const Rect& rect = layout.elements[index].rect;
        int inked = 0;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                if (blank.at(x, y).a <= 0.0f) continue;
                ++inked;
                const bool inside = x >= rect.x && x + 1 <= rect.right() && y >= rect.y && y + 1 <= rect.bottom();
                EXPECT_TRUE(inside) << toString(layout.elements[index].kind) << " \"" << layout.elements[index].text
                                    << "\" inks pixel " << x << "," << y << " outside its rectangle";
                int& owner = owners.owner[std::size_t(y) * std::size_t(size.x) + std::size_t(x)];
                if (owner != kNobody) {
                    const PlacedAnnotation& other = layout.elements[std::size_t(owner == kSeveral ? 0 : owner)];
                    ADD_FAILURE() << "pixel " << x << "," << y << " inked by " << toString(layout.elements[index].kind)
                                  << " \"" << layout.elements[index].text << "\" and " << toString(other.kind) << " \""
                                  << other.text << "\"";
                }
                owner = owner == kNobody ? int(index) : kSeveral;
            }
        EXPECT_GT(inked, 0) << toString(layout.elements[index].kind) << " \"" << layout.elements[index].text
                            << "\" draws nothing";
    }
    return owners;
}

void expectClearPixelAroundText(const InkOwners& owners, const AnnotationLayout& layout) {
    for (int y = 0; y < owners.size.y; ++y)
        for (int x = 0; x < owners.size.x; ++x) {
            const int owner = owners.at(x, y);
            if (owner < 0 || !isText(layout.elements[std::size_t(owner)].kind)) continue;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= owners.size.x || ny >= owners.size.y) continue;
                    const int neighbour = owners.at(nx, ny);
                    if (neighbour == kNobody || neighbour == owner) continue;
                    ADD_FAILURE() << toString(layout.elements[std::size_t(owner)].kind) << " \""
                                  << layout.elements[std::size_t(owner)].text << "\" at " << x << "," << y
                                  << " touches another element's ink at " << nx << "," << ny;
                }
        }
}

TEST(AnnotationPixels, NoPixelIsInkedByTwoElements) {
    const Font font = Font::openDefault();
    for (const LayoutCase& layoutCase : layoutCases())
        for (const glm::ivec2 size : layoutImageSizes()) {
            SCOPED_TRACE(layoutCase.name + " at " + std::to_string(size.x) + "x" + std::to_string(size.y));
            const auto sized = planAt(layoutCase, size, font);
            const InkOwners owners = drawEachAlone(sized->plan, size);
            expectClearPixelAroundText(owners, sized->plan.layout);
            if (::testing::Test::HasFailure()) return;  // one case's report is enough to read
        }
}

}  // namespace
}  // namespace tstyles::testing
