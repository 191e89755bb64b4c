// The colour buffer a frame is rendered into (RGBA32F, premultiplied alpha) and its read-back.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "tstyles/gl/objects.h"
#include "tstyles/image/image.h"

namespace tstyles {

class RenderTarget {
public:
    void resize(glm::ivec2 size);
    void bind() const;
    glm::ivec2 size() const { return size_; }
    const Texture& color() const { return *color_; }
    GLuint framebufferId() const { return framebuffer_->id(); }
    // Reads the pixels back, rows top to bottom (waits for the GPU).
    Image read() const;

private:
    glm::ivec2 size_{0};
    std::optional<Texture> color_;
    std::optional<Framebuffer> framebuffer_;
};

}  // namespace tstyles
