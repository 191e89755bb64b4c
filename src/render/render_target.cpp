// Offscreen colour buffer for a rendered frame.
#include "tstyles/render/render_target.h"

#include <algorithm>

#include "render_size_limits.h"

namespace tstyles {

void RenderTarget::resize(glm::ivec2 size) {
    if (size == size_ && color_) return;
    color_.emplace(Texture::create(GL_TEXTURE_2D));
    glTextureStorage2D(color_->id(), 1, GL_RGBA32F, size.x, size.y);
    requireAllocated(size, "RGBA32F colour buffer");
    color_->setFilter(GL_NEAREST, GL_NEAREST);
    framebuffer_.emplace(Framebuffer::create());
    framebuffer_->attachTexture(GL_COLOR_ATTACHMENT0, *color_);
    const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
    framebuffer_->setDrawBuffers(std::span(&drawBuffer, 1));
    framebuffer_->requireComplete("render target");
    size_ = size;
}

void RenderTarget::bind() const { framebuffer_->bind(); }

Image RenderTarget::read() const {
    Image bottomUp(size_.x, size_.y);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(color_->id(), 0, GL_RGBA, GL_FLOAT, GLsizei(bottomUp.rgba.size() * sizeof(float)),
                      bottomUp.rgba.data());
    Image image(size_.x, size_.y);
    const std::size_t row = std::size_t(size_.x) * 4;
    for (int y = 0; y < size_.y; ++y)
        std::copy_n(bottomUp.rgba.begin() + std::ptrdiff_t(std::size_t(size_.y - 1 - y) * row), row,
                    image.rgba.begin() + std::ptrdiff_t(std::size_t(y) * row));
    return image;
}

}  // namespace tstyles
