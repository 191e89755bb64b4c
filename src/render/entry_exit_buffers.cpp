// Rasterising the proxy boxes into layered entry and exit depth textures.
#include "tstyles/render/entry_exit_buffers.h"

#include <array>

#include "tstyles/render/bindings.h"
#include "tstyles/render/gpu_series.h"

namespace tstyles {

EntryExitBuffers::EntryExitBuffers(const ShaderLibrary& shaders)
    : program_(Program::build(shaders, {{GL_VERTEX_SHADER, "entry_exit.vert"},
                                        {GL_GEOMETRY_SHADER, "entry_exit.geom"},
                                        {GL_FRAGMENT_SHADER, "entry_exit.frag"}})),
      meshProgram_(Program::build(shaders, {{GL_VERTEX_SHADER, "entry_exit_mesh.vert"},
                                            {GL_GEOMETRY_SHADER, "entry_exit.geom"},
                                            {GL_FRAGMENT_SHADER, "entry_exit.frag"}})),
      emptyVertexArray_(VertexArray::create()) {}

void EntryExitBuffers::resize(glm::ivec2 viewport, int layers) {
    if (viewport == size_ && layers == layers_) return;
    auto makeLayers = [&] {
        Texture texture = Texture::create(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(texture.id(), 1, GL_R32F, viewport.x, viewport.y, layers);
        texture.setFilter(GL_NEAREST, GL_NEAREST);
        return texture;
    };
    entry_.emplace(makeLayers());
    exit_.emplace(makeLayers());
    framebuffer_.emplace(Framebuffer::create());
    framebuffer_->attachTexture(GL_COLOR_ATTACHMENT0, *entry_);
    framebuffer_->attachTexture(GL_COLOR_ATTACHMENT1, *exit_);
    const std::array<GLenum, 2> drawBuffers = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    framebuffer_->setDrawBuffers(drawBuffers);
    framebuffer_->requireComplete("entry/exit buffers");
    size_ = viewport;
    layers_ = layers;
}

void EntryExitBuffers::render(const GpuSeries& series, const glm::mat4& viewProjection,
                              const glm::mat4& inverseViewProjection, glm::ivec2 viewport) {
    const int layers = int(std::max<std::size_t>(series.proxyCount(), 1));
    resize(viewport, layers);
    framebuffer_->bind();
    glViewport(0, 0, viewport.x, viewport.y);
    const float noEntry[4] = {binding::kNoEntry, 0, 0, 0};
    const float noExit[4] = {binding::kNoExit, 0, 0, 0};
    glClearNamedFramebufferfv(framebuffer_->id(), GL_COLOR, 0, noEntry);
    glClearNamedFramebufferfv(framebuffer_->id(), GL_COLOR, 1, noExit);

    // Faces are classified in the shader, so no culling; MIN/MAX blending keeps the nearest entry
    // and the farthest exit where faces overlap on screen.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glEnablei(GL_BLEND, 0);
    glEnablei(GL_BLEND, 1);
    glBlendEquationi(0, GL_MIN);
    glBlendEquationi(1, GL_MAX);
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendFunci(1, GL_ONE, GL_ONE);

    emptyVertexArray_.bind();
    for (const Program* program : {&program_, &meshProgram_}) {
        program->set("viewProjection", viewProjection);
        program->set("inverseViewProjection", inverseViewProjection);
        program->set("viewportSize", glm::vec2(viewport));
    }
    if (series.proxyBoxCount() > 0) {
        program_.use();
        glDrawArraysInstanced(GL_TRIANGLES, 0, 36, GLsizei(series.proxyBoxCount()));
    }
    if (series.proxyMeshVertexCount() > 0) {
        meshProgram_.use();
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(series.proxyMeshVertexCount()));
    }

    glDisablei(GL_BLEND, 0);
    glDisablei(GL_BLEND, 1);
    glBlendEquationi(0, GL_FUNC_ADD);
    glBlendEquationi(1, GL_FUNC_ADD);
}

void EntryExitBuffers::bind() const {
    entry_->bindToUnit(binding::kEntryUnit);
    exit_->bindToUnit(binding::kExitUnit);
}

std::size_t EntryExitBuffers::textureBytes() const {
    return 2 * std::size_t(size_.x) * std::size_t(size_.y) * std::size_t(layers_) * sizeof(float);
}

}  // namespace tstyles
