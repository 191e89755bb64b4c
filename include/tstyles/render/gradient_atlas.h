// Precomputed density gradients for lit-sphere styles: the central differences at every node of
// every time-step, computed once per series on the GPU (shaders/gradient_atlas.comp) into a
// texture with the density atlas' layout. A styled sample then reads its gradient with one
// filtered fetch (PRECOMPUTED_GRADIENTS in shaders/gradient.glsl) where it took six. Only for
// series whose grids are all rectilinear (even or uneven axes, missing values or not). On even axes
// the filtered node differences are the six-fetch gradient, to rounding, except within a voxel of a
// grid's face or of missing data; along uneven axes they differ where neighbouring spans do.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>

#include "tstyles/gl/objects.h"
#include "tstyles/gl/program.h"
#include "tstyles/render/atlas_layout.h"
#include "tstyles/render/gpu_series.h"

namespace tstyles {

class GradientAtlas {
public:
    // Whether the gradients of `series` can be precomputed (see above).
    static bool suits(const GpuSeries& series);
    // Texture bytes of the gradient atlas for a density atlas of this layout (RGBA16F texels).
    static std::size_t bytesFor(const AtlasLayout& layout);
    // The program that computes it; built once per renderer.
    static Program buildProgram(const ShaderLibrary& shaders);
    // Computes the gradients of every time-step of `series` (which must suit) with `program`. None
    // where the driver has no memory for the texture: styles then take their six fetches.
    static std::optional<GradientAtlas> compute(const Program& program, const GpuSeries& series);

    void bind() const;
    std::size_t textureBytes() const { return texture_.allocatedBytes(); }

private:
    explicit GradientAtlas(Texture texture) : texture_(std::move(texture)) {}

    Texture texture_;
};

}  // namespace tstyles
