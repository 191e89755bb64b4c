// The densities where the STF's baked table may give some opacity (visibleDensityRange): what the
// walks test before they classify a time-step for a compositor that leaves transparent ones out.
// Closed forms: a lookup at x blends the two entries around x (kTransferTableSize - 1), so x an
// entry and a half or more outside the visible entries reads only transparent ones.
#include <vector>

#include <gtest/gtest.h>

#include "tstyles/render/transfer_tables.h"

namespace tstyles::testing {
namespace {

std::vector<glm::vec4> tableVisibleFrom(int first, int last) {
    std::vector<glm::vec4> table(kTransferTableSize, glm::vec4(1.0f, 1.0f, 1.0f, 0.0f));
    for (int entry = first; entry <= last; ++entry) table[std::size_t(entry)].a = 0.5f;
    return table;
}

TEST(VisibleDensityRange, IsTheVisibleEntriesWithAnEntryAndAHalfOfMarginEachSide) {
    const float step = 1.0f / float(kTransferTableSize - 1);
    const glm::vec2 range = visibleDensityRange(tableVisibleFrom(100, 200));
    EXPECT_FLOAT_EQ(range.x, 98.5f * step);
    EXPECT_FLOAT_EQ(range.y, 201.5f * step);
}

TEST(VisibleDensityRange, ReachesPastTheEndsWhenTheFirstOrLastEntryIsVisible) {
    const glm::vec2 range = visibleDensityRange(tableVisibleFrom(0, kTransferTableSize - 1));
    EXPECT_LT(range.x, 0.0f);
    EXPECT_GT(range.y, 1.0f);
}

TEST(VisibleDensityRange, IsEmptyForATransparentTable) {
    const glm::vec2 range = visibleDensityRange(tableVisibleFrom(1, 0));
    EXPECT_GT(range.x, range.y);
    EXPECT_GT(range.x, 1.0f);
    EXPECT_LT(range.y, 0.0f);
}

TEST(VisibleDensityRange, OfABakedRampStartsWhereItsOpacityDoes) {
    TransferFunction1D ramp;
    ramp.opacity = {{0.0, 0.0}, {0.25, 0.0}, {0.75, 1.0}, {1.0, 1.0}};
    ramp.color = {{0.0, {1.0, 1.0, 1.0}}};
    const glm::vec2 range = visibleDensityRange(bakeTransferTable(ramp));
    const float step = 1.0f / float(kTransferTableSize - 1);
    EXPECT_LE(range.x, 0.25f);
    EXPECT_GE(range.x, 0.25f - 3.0f * step);
    EXPECT_GT(range.y, 1.0f);
}

}  // namespace
}  // namespace tstyles::testing
