// The k-d split of the world for sort-last rendering (block_decomposition.h).
#include "tstyles/distributed/block_decomposition.h"

#include <stdexcept>

namespace tstyles {
namespace {

std::vector<int> primeFactors(int count) {
    std::vector<int> factors;
    for (int divisor = 2; divisor * divisor <= count; ++divisor)
        while (count % divisor == 0) {
            factors.push_back(divisor);
            count /= divisor;
        }
    if (count > 1) factors.push_back(count);
    return factors;
}

int longestAxis(const Bounds& bounds) {
    const glm::dvec3 size = bounds.size();
    return size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
}

}  // namespace

BlockDecomposition::BlockDecomposition(const Bounds& bounds, int processCount)
    : bounds_(bounds), factors_(processCount > 1 ? primeFactors(processCount) : std::vector<int>{}) {
    if (processCount < 1) throw std::invalid_argument("BlockDecomposition: no processes");
    blocks_.assign(std::size_t(processCount), bounds);
    splitAxes_.assign(std::size_t(processCount), std::vector<int>(factors_.size(), 0));
    // From the top level (the last factor) down: each rank's block is the slab of its digit.
    for (int level = int(factors_.size()) - 1; level >= 0; --level)
        for (int rank = 0; rank < processCount; ++rank) {
            Bounds& block = blocks_[std::size_t(rank)];
            const int axis = longestAxis(block);
            const int slabs = factors_[std::size_t(level)];
            const int slab = digit(rank, level);
            const double lower = block.lower[axis];
            const double width = (block.upper[axis] - lower) / slabs;
            block.lower[axis] = lower + width * slab;
            // The last slab ends exactly at the parent's end, so neighbours share their faces.
            if (slab + 1 < slabs) block.upper[axis] = lower + width * (slab + 1);
            splitAxes_[std::size_t(rank)][std::size_t(level)] = axis;
        }
}

int BlockDecomposition::ownerOf(const glm::dvec3& point) const {
    const glm::dvec3 inside = glm::clamp(point, bounds_.lower, bounds_.upper);
    for (std::size_t rank = 0; rank < blocks_.size(); ++rank) {
        const Bounds& block = blocks_[rank];
        bool holds = true;
        for (int axis = 0; axis < 3 && holds; ++axis)
            holds = inside[axis] >= block.lower[axis] &&
                    (inside[axis] < block.upper[axis] || block.upper[axis] == bounds_.upper[axis]);
        if (holds) return int(rank);
    }
    throw std::logic_error("BlockDecomposition::ownerOf: no block holds the point");
}

int BlockDecomposition::digit(int rank, int level) const {
    for (int below = 0; below < level; ++below) rank /= factors_[std::size_t(below)];
    return rank % factors_[std::size_t(level)];
}

int BlockDecomposition::rankWithDigit(int rank, int level, int value) const {
    int weight = 1;
    for (int below = 0; below < level; ++below) weight *= factors_[std::size_t(below)];
    return rank + (value - digit(rank, level)) * weight;
}

int BlockDecomposition::splitAxis(int rank, int level) const {
    return splitAxes_.at(std::size_t(rank)).at(std::size_t(level));
}

}  // namespace tstyles
