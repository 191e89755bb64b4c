// Inverse maps and the per-time-step structured-grid table on the GPU; boundary faces for the
// proxy mesh.
#include "tstyles/render/gpu_structured_grids.h"

#include <algorithm>
#include <array>
#include <span>

#include <glm/gtc/matrix_transform.hpp>

#include "tstyles/data/inverse_map.h"
#include "tstyles/render/shader_contract.h"
#include "tstyles/render/proxy_mesh.h"

namespace tstyles {
namespace {

using contract::StructuredGridInfo;

}  // namespace

glm::dmat4 structuredBoxToWorld(const StructuredGrid& grid, const Placement& placement) {
    const glm::dvec3 voxelSize = (grid.localUpper - grid.localLower) / glm::dvec3(grid.dims - 1);
    return placement.gridToWorld() * glm::translate(glm::dmat4(1.0), grid.localLower) *
           glm::scale(glm::dmat4(1.0), voxelSize);
}

GpuStructuredGrids::GpuStructuredGrids(const Series& series, int firstLayer, std::vector<int>& stepLayers,
                                       std::vector<ProxyMeshVertex>& proxyMesh, int maxTextureSize)
    : inverseMapAtlas_(Texture::create(GL_TEXTURE_3D)), gridTable_(Buffer::create()) {
    // Distinct grids (one inverse map each) and distinct grid + placement pairs (one layer each).
    std::vector<const StructuredGrid*> grids;
    std::vector<int> gridOfStep(series.size(), -1);
    std::vector<std::size_t> firstStepOfLayer;
    for (std::size_t step = 0; step < series.size(); ++step) {
        const StructuredGrid* grid = series.steps[step].structured();
        if (!grid) continue;
        auto known = std::find_if(grids.begin(), grids.end(),
                                  [grid](const StructuredGrid* other) { return other->nodes == grid->nodes; });
        gridOfStep[step] = int(known - grids.begin());
        if (known == grids.end()) grids.push_back(grid);
        auto sameLayer = std::find_if(firstStepOfLayer.begin(), firstStepOfLayer.end(), [&](std::size_t other) {
            return series.steps[other].structured()->nodes == grid->nodes &&
                   series.steps[other].placement == series.steps[step].placement;
        });
        stepLayers[step] = firstLayer + int(sameLayer - firstStepOfLayer.begin());
        if (sameLayer == firstStepOfLayer.end()) {
            firstStepOfLayer.push_back(step);
            appendStructuredProxyMesh(*grid, series.steps[step].placement, stepLayers[step], proxyMesh);
        }
    }
    layerCount_ = int(firstStepOfLayer.size());

    std::vector<InverseMap> maps;
    std::vector<glm::ivec3> mapDims;
    for (const StructuredGrid* grid : grids) {
        maps.push_back(buildInverseMap(*grid, inverseMapDims(*grid)));
        mapDims.push_back(maps.back().dims);
    }
    mapLayout_ = planAtlas(mapDims.empty() ? std::vector<glm::ivec3>{glm::ivec3(1)} : mapDims, maxTextureSize);
    glTextureStorage3D(inverseMapAtlas_.id(), 1, GL_RGBA32F, mapLayout_.size.x, mapLayout_.size.y, mapLayout_.size.z);
    inverseMapAtlas_.setFilter(GL_LINEAR, GL_LINEAR);
    inverseMapAtlas_.setClampToEdge();
    for (std::size_t index = 0; index < maps.size(); ++index) {
        const glm::ivec3 origin = mapLayout_.brickOrigins[index];
        glTextureSubImage3D(inverseMapAtlas_.id(), 0, origin.x, origin.y, origin.z, maps[index].dims.x,
                            maps[index].dims.y, maps[index].dims.z, GL_RGBA, GL_FLOAT, maps[index].texels.data());
    }

    std::vector<StructuredGridInfo> table(std::max<std::size_t>(series.size(), 1),
                                          {glm::vec4(0.0f), glm::vec4(1.0f)});
    for (std::size_t step = 0; step < series.size(); ++step) {
        if (gridOfStep[step] < 0) continue;
        const auto gridIndex = std::size_t(gridOfStep[step]);
        const StructuredGrid& grid = *grids[gridIndex];
        const glm::vec3 scale = glm::vec3(maps[gridIndex].dims - 1) / glm::vec3(grid.dims - 1);
        table[step] = {glm::vec4(glm::vec3(mapLayout_.brickOrigins[gridIndex]), 1.0f),
                       glm::vec4(scale, float(0.5 * grid.finestEdge))};
    }
    gridTable_.setData(std::as_bytes(std::span(table)), GL_STATIC_DRAW);
}

std::size_t GpuStructuredGrids::gpuBytes() const {
    return inverseMapAtlas_.allocatedBytes();
}

void GpuStructuredGrids::bind() const {
    inverseMapAtlas_.bindToUnit(contract::INVERSE_MAP_UNIT);
    gridTable_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::STRUCTURED_GRID_BUFFER);
}

}  // namespace tstyles
