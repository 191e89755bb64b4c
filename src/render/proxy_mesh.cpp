// Beam fans and structured grids' boundary faces as world-space proxy triangles for the
// entry/exit buffers.
#include "tstyles/render/proxy_mesh.h"

#include <array>

#include "tstyles/data/beam_geometry.h"

namespace tstyles {

void appendBeamProxyMesh(const TimeStep& step, int layer, std::vector<ProxyMeshVertex>& mesh) {
    const glm::dmat4 toWorld = step.placement.gridToWorld();
    for (const Triangle& triangle : beamFanBoundary(step.beam())) {
        glm::dvec3 world[3];
        for (int corner = 0; corner < 3; ++corner) world[corner] = glm::dvec3(toWorld * glm::dvec4(triangle[corner], 1.0));
        const glm::dvec3 cross = glm::cross(world[1] - world[0], world[2] - world[0]);
        // Degenerate triangles (the sides meet at the transducer when the near range is 0) cover
        // no pixels; they are left out rather than given a meaningless normal.
        if (glm::length(cross) <= 0.0) continue;
        const glm::vec4 normal(glm::vec3(glm::normalize(cross)), 0.0f);
        for (const glm::dvec3& corner : world) mesh.push_back({glm::vec4(glm::vec3(corner), float(layer)), normal});
    }
}

void appendStructuredProxyMesh(const StructuredGrid& grid, const Placement& placement, int layer,
                               std::vector<ProxyMeshVertex>& mesh) {
    const glm::dmat4 toWorld = placement.gridToWorld();
    const glm::dmat3 rotate = glm::mat3_cast(placement.rotation);
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3;
        const int v = (axis + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            const int level = side ? grid.dims[axis] - 1 : 0;
            const int inwardStep = side ? -1 : 1;
            auto nodeAt = [&](int a, int b, int c) {
                glm::ivec3 index(0);
                index[axis] = a;
                index[u] = b;
                index[v] = c;
                return grid.node(index.x, index.y, index.z);
            };
            for (int b = 0; b + 1 < grid.dims[u]; ++b)
                for (int c = 0; c + 1 < grid.dims[v]; ++c) {
                    const glm::dvec3 quad[4] = {nodeAt(level, b, c), nodeAt(level, b + 1, c),
                                                nodeAt(level, b + 1, c + 1), nodeAt(level, b, c + 1)};
                    const glm::dvec3 inward = nodeAt(level + inwardStep, b, c) - quad[0];
                    for (const auto& triangle : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
                        const glm::dvec3& a = quad[triangle[0]];
                        glm::dvec3 normal = glm::cross(quad[triangle[1]] - a, quad[triangle[2]] - a);
                        if (glm::dot(normal, inward) > 0.0) normal = -normal;
                        const double length = glm::length(normal);
                        if (!(length > 0.0)) continue;
                        const glm::vec4 worldNormal(glm::vec3(rotate * (normal / length)), 0.0f);
                        for (int corner : triangle) {
                            const glm::dvec3 world(toWorld * glm::dvec4(quad[corner], 1.0));
                            mesh.push_back({glm::vec4(glm::vec3(world), float(layer)), worldNormal});
                        }
                    }
                }
        }
    }
}

}  // namespace tstyles
