// Rasterising the proxies into a layered texture of entry and exit depths.
#include "tstyles/render/raycast_uniforms.h"
#include "tstyles/render/entry_exit_buffers.h"

#include <array>

#include "render_size_limits.h"

#include "tstyles/render/shader_contract.h"
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
    requireRenderableSize(viewport, layers);
    Texture depths = Texture::create(GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(depths.id(), 1, GL_RG32F, viewport.x, viewport.y, layers);
    requireAllocated(viewport, "entry/exit depth layers");
    depths.setFilter(GL_NEAREST, GL_NEAREST);
    depths_.emplace(std::move(depths));
    framebuffer_.emplace(Framebuffer::create());
    framebuffer_->attachTexture(GL_COLOR_ATTACHMENT0, *depths_);
    const std::array<GLenum, 1> drawBuffers = {GL_COLOR_ATTACHMENT0};
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
    // Entry in red, the negated exit in green: one MIN blend keeps the nearest entry and the
    // farthest exit where faces overlap on screen, and the raycaster reads both with one fetch.
    const float nothing[4] = {contract::NO_ENTRY, -contract::NO_EXIT, 0, 0};
    glClearNamedFramebufferfv(framebuffer_->id(), GL_COLOR, 0, nothing);

    // Faces are classified in the shader, so no culling.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glEnablei(GL_BLEND, 0);
    glBlendEquationi(0, GL_MIN);
    glBlendFunci(0, GL_ONE, GL_ONE);

    emptyVertexArray_.bind();
    for (const Program* program : {&program_, &meshProgram_}) {
        program->set("viewProjection", viewProjection);
        // The ray's uniforms (ray.glsl), which the raycasting program shares.
        program->set(raycast_uniform::inverseViewProjection, inverseViewProjection);
        program->set(raycast_uniform::viewportSize, glm::vec2(viewport));
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
    glBlendEquationi(0, GL_FUNC_ADD);
}

void EntryExitBuffers::bind() const {
    depths_->bindToUnit(contract::ENTRY_EXIT_UNIT);
}

std::size_t EntryExitBuffers::textureBytes() const {
    return 2 * std::size_t(size_.x) * std::size_t(size_.y) * std::size_t(layers_) * sizeof(float);
}

}  // namespace tstyles
