// The GPU side of explicit structured grids: every distinct grid's inverse map packed into one
// RGBA32F 3D texture, a per-time-step table telling the shaders which time-steps are structured and
// where their map is; the grids' boundary faces go into the proxy mesh of the entry/exit buffers.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/gl/objects.h"
#include "tstyles/render/atlas_layout.h"
#include "tstyles/render/proxy_mesh.h"

namespace tstyles {

class GpuStructuredGrids {
public:
    // Builds the inverse maps (on the CPU, once per distinct grid) and appends the boundary faces to
    // `proxyMesh` (once per distinct grid and placement, each in its own entry/exit layer from
    // `firstLayer` on). Writes the layer of every structured time-step into `stepLayers` (sized to
    // the series).
    GpuStructuredGrids(const Series& series, int firstLayer, std::vector<int>& stepLayers,
                       std::vector<ProxyMeshVertex>& proxyMesh, int maxTextureSize);

    int layerCount() const { return layerCount_; }
    // Bytes of the inverse-map atlas.
    std::size_t gpuBytes() const;

    // Binds the inverse-map atlas and the per-time-step table.
    void bind() const;

private:
    int layerCount_ = 0;
    AtlasLayout mapLayout_;
    Texture inverseMapAtlas_;
    Buffer gridTable_;
};

// The world-to-voxel matrix the time-step table holds for a structured time-step: world position
// to the lattice of dims nodes spread evenly over the grid's local bounds (the inverse map's frame).
glm::dmat4 structuredBoxToWorld(const StructuredGrid& grid, const Placement& placement);

}  // namespace tstyles
