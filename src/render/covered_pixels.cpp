// Screen-space bounds of a world box (covered_pixels.h).
#include "tstyles/render/covered_pixels.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tstyles {

PixelRectangle coveredPixels(const Bounds& box, const glm::dmat4& viewProjection, glm::ivec2 viewport) {
    const PixelRectangle whole{{0, 0}, viewport};
    glm::dvec2 lower(std::numeric_limits<double>::infinity());
    glm::dvec2 upper(-std::numeric_limits<double>::infinity());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 point((corner & 1) ? box.upper.x : box.lower.x, (corner & 2) ? box.upper.y : box.lower.y,
                               (corner & 4) ? box.upper.z : box.lower.z);
        const glm::dvec4 clip = viewProjection * glm::dvec4(point, 1.0);
        if (!(clip.w > 1e-12)) return whole;
        const glm::dvec2 window = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(viewport);
        lower = glm::min(lower, window);
        upper = glm::max(upper, window);
    }
    // The box's projection lies inside the corners' hull; a pixel is shaded at its centre, so the
    // pixels whose centres the hull can reach are floor(lower) to ceil(upper), plus a pixel of margin
    // for rounding.
    const double limitX = double(viewport.x);
    const double limitY = double(viewport.y);
    const int x0 = int(std::clamp(std::floor(lower.x) - 1.0, 0.0, limitX));
    const int y0 = int(std::clamp(std::floor(lower.y) - 1.0, 0.0, limitY));
    const int x1 = int(std::clamp(std::ceil(upper.x) + 1.0, 0.0, limitX));
    const int y1 = int(std::clamp(std::ceil(upper.y) + 1.0, 0.0, limitY));
    return {{x0, y0}, {std::max(0, x1 - x0), std::max(0, y1 - y0)}};
}

}  // namespace tstyles
