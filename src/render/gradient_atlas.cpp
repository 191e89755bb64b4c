// The gradient atlas: computed on the GPU from the density atlas, one dispatch per time-step.
#include "tstyles/render/gradient_atlas.h"

#include <utility>

#include "tstyles/render/shader_contract.h"

namespace tstyles {
namespace {

// Nodes per work group of shaders/gradient_atlas.comp: its local size, one node per invocation.
constexpr glm::ivec3 kNodesPerWorkGroup{8, 8, 4};
constexpr GLenum kTexelFormat = GL_RGBA16F;
constexpr std::size_t kBytesPerTexel = 8;

GLuint groupsFor(int texels, int groupSize) { return GLuint((texels + groupSize - 1) / groupSize); }

}  // namespace

bool GradientAtlas::suits(const GpuSeries& series) {
    return !series.hasBeamGrids() && series.structuredGrids().layerCount() == 0;
}

std::size_t GradientAtlas::bytesFor(const AtlasLayout& layout) { return layout.texelCount() * kBytesPerTexel; }

Program GradientAtlas::buildProgram(const ShaderLibrary& shaders) {
    return Program::build(shaders, {{GL_COMPUTE_SHADER, "gradient_atlas.comp"}});
}

std::optional<GradientAtlas> GradientAtlas::compute(const Program& program, const GpuSeries& series) {
    const AtlasLayout& layout = series.layout();
    Texture texture = Texture::create(GL_TEXTURE_3D);
    glTextureStorage3D(texture.id(), 1, kTexelFormat, layout.size.x, layout.size.y, layout.size.z);
    if (glGetError() == GL_OUT_OF_MEMORY) return std::nullopt;
    texture.setFilter(GL_LINEAR, GL_LINEAR);
    texture.setClampToEdge();

    series.bind();  // the density atlas and the time-step table
    glBindImageTexture(GLuint(contract::GRADIENT_IMAGE_UNIT), texture.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       kTexelFormat);
    program.use();
    // Every brick fits in a cell (atlas_layout.h); invocations beyond a brick's dims do nothing.
    const glm::ivec3 cell = layout.cellSize;
    for (std::size_t step = 0; step < series.timeStepCount(); ++step) {
        program.set("step", int(step));
        glDispatchCompute(groupsFor(cell.x, kNodesPerWorkGroup.x), groupsFor(cell.y, kNodesPerWorkGroup.y),
                          groupsFor(cell.z, kNodesPerWorkGroup.z));
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindImageTexture(GLuint(contract::GRADIENT_IMAGE_UNIT), 0, 0, GL_TRUE, 0, GL_WRITE_ONLY, kTexelFormat);
    return GradientAtlas(std::move(texture));
}

void GradientAtlas::bind() const { texture_.bindToUnit(GLuint(contract::GRADIENT_ATLAS_UNIT)); }

}  // namespace tstyles
