// Turning a file's voxel-to-world axes (NRRD space directions, NIfTI qform/sform) into our grid
// spacing and a rigid placement. Our placements are rotations, so a mirrored frame (determinant < 0,
// common in radiological images) is made right-handed by reversing the x axis of the data.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"

namespace tstyles {

struct OrientedAxes {
    glm::dvec3 spacing{1.0};
    Placement placement;
    bool mirrorX = false;  // the values must be reversed along x (mirrorAlongX)
};

// `axes[i]` is the world step of one voxel along grid axis i; `origin` the world position of voxel
// (0,0,0). Axes must be non-zero and orthogonal (a sheared grid is an InputError naming `field`).
OrientedAxes orientAxes(const glm::dvec3& origin, const std::array<glm::dvec3, 3>& axes, const glm::ivec3& dims,
                        const std::filesystem::path& file, const std::string& field);

void mirrorAlongX(std::vector<float>& values, const glm::ivec3& dims);

}  // namespace tstyles
