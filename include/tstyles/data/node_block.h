// A block of a grid's nodes: the first node and how many along x, y and z (what one process keeps
// of a time-step, series_crop.h).
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

namespace tstyles {

struct NodeBlock {
    glm::ivec3 first{0};
    glm::ivec3 count{0};

    std::size_t nodeCount() const { return std::size_t(count.x) * std::size_t(count.y) * std::size_t(count.z); }
    bool contains(const glm::ivec3& node) const {
        return glm::all(glm::greaterThanEqual(node, first)) && glm::all(glm::lessThan(node, first + count));
    }
};

}  // namespace tstyles
