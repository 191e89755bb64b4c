// An RGBA float image with associated (premultiplied) alpha, rows top to bottom.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace tstyles {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;  // width * height * 4

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(std::size_t(w) * std::size_t(h) * 4, 0.0f) {}

    glm::vec4 at(int x, int y) const {
        const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }
    void set(int x, int y, const glm::vec4& value) {
        const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
        rgba[i] = value.r;
        rgba[i + 1] = value.g;
        rgba[i + 2] = value.b;
        rgba[i + 3] = value.a;
    }
};

}  // namespace tstyles
