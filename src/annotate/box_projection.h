// The series' bounding box seen through the view: its corners in the image, and which of each
// axis's four edges carries the axis's ticks. Private to src/annotate.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/scene/camera.h"

namespace tstyles {

// Pixel position of a display-space point; none behind the eye.
std::optional<glm::dvec2> projectToImage(const View& view, glm::ivec2 imageSize, const glm::dvec3& point);

// Corner `bits` of the box: bit k set takes the upper end of axis k.
glm::dvec3 boxCorner(const Bounds& bounds, int bits);

// An edge along `axis` from corner `from` (bit `axis` clear) to corner `from | 1 << axis`.
struct BoxEdge {
    int axis = 0;
    int from = 0;
    glm::dvec2 start{0.0};  // in the image
    glm::dvec2 end{0.0};
};

// The axis's four edges, best first for carrying its ticks: edges on the box's outline (one of the
// faces it joins faces the viewer, the other faces away) before the others and, of those, the
// nearest the viewer, so that labels stand outside the box on the side toward the viewer; on a tie
// the lower one (the left one for the vertical axis). Edges whose middle is off the image or
// shorter than `shortest` pixels come last; edges behind the eye are left out.
std::vector<BoxEdge> tickEdges(const View& view, glm::ivec2 imageSize, const Bounds& bounds, int axis,
                               double shortest);

}  // namespace tstyles
