// Entry and exit buffers (paper 5.1): for every distinct time-step placement, the ray parameter at
// which each pixel's ray enters and leaves its proxy, in one layered RG32F texture (one layer
// each, so that the number of time-steps is not bounded by texture units): entry in red, the
// negated exit in green, so that one fetch gives both.
#pragma once

#include <glm/glm.hpp>

#include "tstyles/gl/objects.h"
#include "tstyles/gl/program.h"

namespace tstyles {

class GpuSeries;

class EntryExitBuffers {
public:
    explicit EntryExitBuffers(const ShaderLibrary& shaders);

    // Rasterises every proxy box of `series` into its layer. `series` must be bound (GpuSeries::bind).
    void render(const GpuSeries& series, const glm::mat4& viewProjection, const glm::mat4& inverseViewProjection,
                glm::ivec2 viewport);
    void bind() const;
    std::size_t textureBytes() const;

private:
    void resize(glm::ivec2 viewport, int layers);

    Program program_;      // instanced proxy boxes
    Program meshProgram_;  // proxy meshes (beam fans, boundary faces of structured grids)
    VertexArray emptyVertexArray_;
    glm::ivec2 size_{0};
    int layers_ = 0;
    std::optional<Texture> depths_;
    std::optional<Framebuffer> framebuffer_;
};

}  // namespace tstyles
