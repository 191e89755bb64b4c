// Beam fans as world-space proxy triangles for the entry/exit buffers.
#include "tstyles/render/proxy_mesh.h"

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

}  // namespace tstyles
