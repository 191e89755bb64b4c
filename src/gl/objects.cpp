// Creation and the few operations of the RAII GL object types.
#include "tstyles/gl/objects.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace tstyles {

Texture Texture::create(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return Texture(target, id);
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) const {
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GLint(minFilter));
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GLint(magFilter));
}

void Texture::setClampToEdge() const {
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

std::size_t Texture::allocatedBytes() const {
    const auto level0 = [this](GLenum name) {
        GLint value = 0;
        glGetTextureLevelParameteriv(id(), 0, name, &value);
        return std::size_t(std::max(value, 0));
    };
    const std::size_t bits = level0(GL_TEXTURE_RED_SIZE) + level0(GL_TEXTURE_GREEN_SIZE) +
                             level0(GL_TEXTURE_BLUE_SIZE) + level0(GL_TEXTURE_ALPHA_SIZE);
    return level0(GL_TEXTURE_WIDTH) * level0(GL_TEXTURE_HEIGHT) * level0(GL_TEXTURE_DEPTH) * bits / 8;
}

Buffer Buffer::create() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return Buffer(id);
}

void Buffer::clearToZero() const {
    const std::uint32_t zero = 0;
    glClearNamedBufferData(id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void Buffer::setData(std::span<const std::byte> bytes, GLenum usage) const {
    // A zero-sized store cannot be bound as a shader storage block; keep at least 16 bytes.
    static const std::byte padding[16] = {};
    if (bytes.empty()) bytes = std::span<const std::byte>(padding, sizeof padding);
    glNamedBufferData(id(), GLsizeiptr(bytes.size()), bytes.data(), usage);
}

Framebuffer Framebuffer::create() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return Framebuffer(id);
}

void Framebuffer::attachTexture(GLenum attachment, const Texture& texture, GLint level) const {
    glNamedFramebufferTexture(id(), attachment, texture.id(), level);
}

void Framebuffer::setDrawBuffers(std::span<const GLenum> buffers) const {
    glNamedFramebufferDrawBuffers(id(), GLsizei(buffers.size()), buffers.data());
}

void Framebuffer::requireComplete(const char* what) const {
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error(std::string(what) + ": framebuffer incomplete (status 0x" +
                                 [](GLenum value) {
                                     char text[16];
                                     std::snprintf(text, sizeof text, "%04x", value);
                                     return std::string(text);
                                 }(status) +
                                 ")");
}

VertexArray VertexArray::create() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return VertexArray(id);
}

TimerQuery TimerQuery::create() {
    GLuint id = 0;
    glCreateQueries(GL_TIME_ELAPSED, 1, &id);
    return TimerQuery(id);
}

double TimerQuery::milliseconds() const {
    GLuint64 elapsedNs = 0;
    glGetQueryObjectui64v(query_.id(), GL_QUERY_RESULT, &elapsedNs);
    return double(elapsedNs) * 1e-6;
}

}  // namespace tstyles
