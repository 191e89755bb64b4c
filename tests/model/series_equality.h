// Two series the same to the bit, field by field (values compared as bytes, so NaN payloads and
// signed zeros count): for the isolated reading and the series transfer, which must not change a
// thing.
#pragma once

#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tstyles/data/series.h"

namespace tstyles_test {

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline void expectSameGrid(const tstyles::Grid& a, const tstyles::Grid& b, const std::string& where) {
    using namespace tstyles;
    ASSERT_EQ(a.index(), b.index()) << where;
    if (const auto* ra = std::get_if<RectilinearGrid>(&a)) {
        const auto& rb = std::get<RectilinearGrid>(b);
        EXPECT_EQ(ra->dims, rb.dims) << where;
        EXPECT_EQ(std::memcmp(&ra->spacing, &rb.spacing, sizeof ra->spacing), 0) << where;
        for (std::size_t axis = 0; axis < 3; ++axis)
            EXPECT_TRUE(sameBytes(ra->axisPositions[axis], rb.axisPositions[axis])) << where << " axis " << axis;
    } else if (const auto* sa = std::get_if<StructuredGrid>(&a)) {
        const auto& sb = std::get<StructuredGrid>(b);
        EXPECT_EQ(sa->dims, sb.dims) << where;
        EXPECT_EQ(sa->coordinatesFile, sb.coordinatesFile) << where;
        EXPECT_EQ(sa->localLower, sb.localLower) << where;
        EXPECT_EQ(sa->localUpper, sb.localUpper) << where;
        EXPECT_EQ(sa->finestEdge, sb.finestEdge) << where;
        ASSERT_EQ(bool(sa->nodes), bool(sb.nodes)) << where;
        if (sa->nodes) {
            EXPECT_TRUE(sameBytes(*sa->nodes, *sb.nodes)) << where;
        }
    } else {
        EXPECT_TRUE(std::get<BeamGrid>(a) == std::get<BeamGrid>(b)) << where;
    }
}

inline void expectSameSeries(const tstyles::Series& a, const tstyles::Series& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.manifestPath, b.manifestPath);
    EXPECT_EQ(std::memcmp(a.valueRange.data(), b.valueRange.data(), sizeof a.valueRange), 0);
    EXPECT_EQ(a.valueUnit, b.valueUnit);
    EXPECT_EQ(a.precision, b.precision);
    EXPECT_EQ(a.sourceFormat, b.sourceFormat);
    EXPECT_EQ(a.readingNotes, b.readingNotes);
    EXPECT_EQ(a.axes, b.axes);
    EXPECT_EQ(a.time, b.time);
    ASSERT_EQ(a.steps.size(), b.steps.size());
    for (std::size_t index = 0; index < a.steps.size(); ++index) {
        const tstyles::TimeStep& sa = a.steps[index];
        const tstyles::TimeStep& sb = b.steps[index];
        const std::string where = "time-step " + std::to_string(index);
        EXPECT_EQ(std::memcmp(&sa.time, &sb.time, sizeof sa.time), 0) << where;
        expectSameGrid(sa.grid, sb.grid, where);
        EXPECT_TRUE(sa.placement == sb.placement) << where;
        EXPECT_EQ(sa.sourceType, sb.sourceType) << where;
        EXPECT_EQ(std::memcmp(sa.rawRange.data(), sb.rawRange.data(), sizeof sa.rawRange), 0) << where;
        EXPECT_TRUE(sameBytes(sa.density, sb.density)) << where;
        ASSERT_EQ(sa.mask.has_value(), sb.mask.has_value()) << where;
        if (sa.mask) {
            EXPECT_TRUE(sameBytes(*sa.mask, *sb.mask)) << where;
        }
        EXPECT_EQ(sa.valuesFile, sb.valuesFile) << where;
        EXPECT_EQ(sa.maskFile, sb.maskFile) << where;
    }
}

}  // namespace tstyles_test
