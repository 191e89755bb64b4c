// Small RAII types for the GL objects the renderer uses. No raw glCreate*/glDelete* elsewhere.
#pragma once

#include <cstddef>
#include <span>

#include <glm/glm.hpp>

#include "tstyles/gl/handle.h"

namespace tstyles {

class Texture {
public:
    // An immutable-storage texture of `target` (GL_TEXTURE_1D, _2D_ARRAY, _3D, ...).
    static Texture create(GLenum target);
    GLuint id() const { return handle_.id(); }
    GLenum target() const { return target_; }
    void bindToUnit(GLuint unit) const { glBindTextureUnit(unit, id()); }
    void setFilter(GLenum minFilter, GLenum magFilter) const;
    void setClampToEdge() const;
    // Bytes of level 0 as the driver reports its storage: width x height x depth x the bits of its
    // channels (0 for a texture without storage).
    std::size_t allocatedBytes() const;

private:
    Texture(GLenum target, GLuint id) : target_(target), handle_(id) {}
    GLenum target_ = 0;
    GlHandle<TextureTraits> handle_;
};

class Buffer {
public:
    static Buffer create();
    GLuint id() const { return handle_.id(); }
    // Replaces the contents (the buffer grows or shrinks to `bytes`).
    void setData(std::span<const std::byte> bytes, GLenum usage = GL_DYNAMIC_DRAW) const;
    // Sets every byte to 0 in place, on the GPU (no upload, no reallocation).
    void clearToZero() const;
    void bindBase(GLenum target, GLuint index) const { glBindBufferBase(target, index, id()); }

private:
    explicit Buffer(GLuint id) : handle_(id) {}
    GlHandle<BufferTraits> handle_;
};

template <typename T>
std::span<const std::byte> bytesOf(std::span<const T> values) {
    return std::as_bytes(values);
}

class Framebuffer {
public:
    static Framebuffer create();
    GLuint id() const { return handle_.id(); }
    void attachTexture(GLenum attachment, const Texture& texture, GLint level = 0) const;
    void setDrawBuffers(std::span<const GLenum> buffers) const;
    // Throws std::runtime_error with the status name if the framebuffer is not complete.
    void requireComplete(const char* what) const;
    void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id()); }

private:
    explicit Framebuffer(GLuint id) : handle_(id) {}
    GlHandle<FramebufferTraits> handle_;
};

class VertexArray {
public:
    static VertexArray create();
    GLuint id() const { return handle_.id(); }
    void bind() const { glBindVertexArray(id()); }

private:
    explicit VertexArray(GLuint id) : handle_(id) {}
    GlHandle<VertexArrayTraits> handle_;
};

// The GPU time of the commands between begin() and end() (GL_TIME_ELAPSED). One such query runs at
// a time. A GPU's; llvmpipe stamps commands when it queues them, not when its threads rasterize
// them, so its readings are not the pass' time (render/pass_clock.h).
class TimerQuery {
public:
    static TimerQuery create();
    void begin() const { glBeginQuery(GL_TIME_ELAPSED, query_.id()); }
    void end() const { glEndQuery(GL_TIME_ELAPSED); }
    // Waits for the result; milliseconds the GPU spent between begin() and end().
    double milliseconds() const;

private:
    explicit TimerQuery(GLuint query) : query_(query) {}
    GlHandle<QueryTraits> query_;
};

}  // namespace tstyles
