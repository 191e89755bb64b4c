// How N processes split the world for sort-last rendering: a k-d tree over the series' bounds
// whose levels cut each block into `factors` slabs along its longest axis (N's prime factors), so
// that the blocks of one level's group are slabs of one parent block, and radix-k compositing
// (sort_last_compositing.h) can merge each group in visibility order.
#pragma once

#include <vector>

#include "tstyles/data/series.h"

namespace tstyles {

class BlockDecomposition {
public:
    // Splits `bounds` for `processCount` >= 1 processes.
    BlockDecomposition(const Bounds& bounds, int processCount);

    int processCount() const { return int(blocks_.size()); }
    // The slabs per level, deepest level (the first compositing round) first; their product is
    // processCount(). Empty for one process.
    const std::vector<int>& factors() const { return factors_; }
    const Bounds& block(int rank) const { return blocks_.at(std::size_t(rank)); }
    // The one rank whose block holds `point`: blocks are half-open at the faces they share, and a
    // point outside the split bounds counts as at their nearest face. So every process gives each
    // point the same owner, which statistics taken over the blocks count once.
    int ownerOf(const glm::dvec3& point) const;
    // A rank's digit at `level`: which slab of its parent block it is (rank = d0 + k0 (d1 + k1 (...)))
    int digit(int rank, int level) const;
    // The rank whose digit at `level` is `value` and whose other digits are `rank`'s.
    int rankWithDigit(int rank, int level, int value) const;
    // The axis along which the parent block of `rank` at `level` was cut; slab 0 is at its lower
    // end, so slab order along the axis is digit order.
    int splitAxis(int rank, int level) const;

private:
    Bounds bounds_;
    std::vector<int> factors_;
    std::vector<Bounds> blocks_;
    std::vector<std::vector<int>> splitAxes_;  // per rank, per level
};

}  // namespace tstyles
