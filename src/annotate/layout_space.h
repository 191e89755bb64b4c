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

// A convex polygon on the image, its corners in order (the picture's data as the view projects
// its bounds).
using Outline = std::vector<glm::dvec2>;
// The convex hull of the points, counter-clockwise in image pixels; collinear points left out.
Outline convexHull(std::vector<glm::dvec2> points);
// True where the rectangle and the outline share some area (touching does not count).
bool rectMeetsOutline(const Rect& rect, const Outline& outline);

class LayoutSpace {
public:
    // `margin`: the panels' distance from the image's edges; half of it lies between stacked
    // panels.
    LayoutSpace(glm::ivec2 imageSize, double margin);

    glm::ivec2 imageSize() const { return size_; }
    double margin() const { return margin_; }
    bool insideImage(const Rect& rect) const;
    // Inside the image and clear of everything claimed, of the outlines kept clear and of
    // `alsoAvoid`.
    bool isFree(const Rect& rect, const std::vector<Rect>& alsoAvoid = {}) const;
    void claim(const Rect& rect) { claimed_.push_back(rect); }
    // Nothing placed from now on meets the outline (the picture's data).
    void keepClearOf(Outline outline) { kept_.push_back(std::move(outline)); }

    // A panel of this size (rounded out to whole pixels) in the corner, next to the panels already
    // stacked there, moved further inward past anything in its way (past an outline's bounding
    // rectangle); claimed. None where it would leave the image.
    std::optional<Rect> placeInCorner(Corner corner, double width, double height);

private:
    glm::ivec2 size_;
    double margin_;
    std::vector<Rect> claimed_;
    std::vector<Outline> kept_;
    // Per corner, the row the next panel starts at: its top for a top corner, its bottom else.
    std::map<Corner, double> nextEdge_;
};

}  // namespace tstyles
