// Proxy meshes for the entry/exit buffers of grids that are not boxes: a beam fan's enclosing
// triangles or a structured grid's boundary faces, in world space, tagged with the grid's layer
// (mirrors shaders/proxy_mesh.glsl).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/render/shader_contract.h"

namespace tstyles {

// A vertex of the proxy mesh table (ProxyVertex in shaders/contract.glsl).
using ProxyMeshVertex = contract::ProxyVertex;

// Appends the enclosing mesh of a beam time-step's fan (tstyles/data/beam_geometry.h), placed in
// the world, three vertices per triangle.
void appendBeamProxyMesh(const TimeStep& step, int layer, std::vector<ProxyMeshVertex>& mesh);

// Appends the six boundary faces of a structured grid, placed in the world, as triangles with
// normals pointing out of the grid.
void appendStructuredProxyMesh(const StructuredGrid& grid, const Placement& placement, int layer,
                               std::vector<ProxyMeshVertex>& mesh);

}  // namespace tstyles
