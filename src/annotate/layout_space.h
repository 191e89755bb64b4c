// The image's free space as the annotations' layout fills it: rectangles claimed one after the
// other, none overlapping another or leaving the image, panels stacked inward from the corners.
// Private to src/annotate.
#pragma once

#include <map>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/annotate/canvas.h"
#include "tstyles/scene/annotations.h"

namespace tstyles {

// True where the two rectangles share some area (touching edges do not).
bool rectsOverlap(const Rect& a, const Rect& b);

class LayoutSpace {
public:
    // `margin`: the panels' distance from the image's edges; half of it lies between stacked
    // panels.
    LayoutSpace(glm::ivec2 imageSize, double margin);

    glm::ivec2 imageSize() const { return size_; }
    double margin() const { return margin_; }
    bool insideImage(const Rect& rect) const;
    // Inside the image and clear of everything claimed and of `alsoAvoid`.
    bool isFree(const Rect& rect, const std::vector<Rect>& alsoAvoid = {}) const;
    void claim(const Rect& rect) { claimed_.push_back(rect); }

    // A panel of this size (rounded out to whole pixels) in the corner, next to the panels already
    // stacked there, moved further inward past anything in its way; claimed. None where it would
    // leave the image.
    std::optional<Rect> placeInCorner(Corner corner, double width, double height);

private:
    glm::ivec2 size_;
    double margin_;
    std::vector<Rect> claimed_;
    // Per corner, the row the next panel starts at: its top for a top corner, its bottom else.
    std::map<Corner, double> nextEdge_;
};

}  // namespace tstyles
