// Where the picture goes beside the annotations' panels: the data's footprint on the image (its
// bounds as the view projects them) moved and shrunk, as little as it takes, into the room that
// the panels leave, so that no panel covers data (docs/annotations.md, "Layout").
// Private to src/annotate.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "layout_space.h"
#include "tstyles/annotate/canvas.h"
#include "tstyles/data/series.h"
#include "tstyles/scene/camera.h"

namespace tstyles {

// The convex outline (image pixels, y down) of the bounds' eight corners as the view projects them;
// none where a corner lies behind the eye.
std::optional<Outline> outlineOnImage(const View& view, glm::ivec2 imageSize, const Bounds& bounds);

// The rectangle (image pixels, y down) that holds the bounds' eight corners as the view projects
// them, also where it reaches past the image (a camera close to the data); none where a corner
// lies behind the eye or the rectangle misses the image.
std::optional<Rect> footprintOnImage(const View& view, glm::ivec2 imageSize, const Bounds& bounds);

// A move of the picture on the image: a pixel p goes to `to + scale * (p - from)`.
struct PictureMove {
    double scale = 1.0;
    glm::dvec2 from{0.0};
    glm::dvec2 to{0.0};
    bool isIdentity() const { return scale == 1.0 && from == to; }
    Rect apply(const Rect& rect) const;
};

// The move that puts `footprint` clear of every obstacle, `gap` pixels away from each: none where
// it is clear already; else into the free rectangle of the image (`gap` inside its edges) that
// holds it largest (never larger than it is), nearest to where it was. The scale is 0 where no
// free rectangle is left.
PictureMove moveClearOf(const Rect& footprint, glm::ivec2 imageSize, const std::vector<Rect>& obstacles, double gap);

// How large the picture is after the move against its part on the image before it (where the
// camera showed only part of the data, the move that frames all of it keeps more than its scale).
double shareKept(const Rect& footprint, const PictureMove& move, glm::ivec2 imageSize);

// The view whose picture is `view`'s moved on the image: the projection followed by the move in
// normalized device coordinates (exact for perspective and orthographic cameras alike).
View movedOnImage(const View& view, glm::ivec2 imageSize, const PictureMove& move);

}  // namespace tstyles
