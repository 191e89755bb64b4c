// The coast of a map: where the surface of a geographic series (the top level along the display's
// up axis) has no data in the first time-step (land, as ocean files store it) beside a place that
// has, a line along the edge between them at the surface's height. Private to src/annotate.
#pragma once

#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/annotate/canvas.h"
#include "tstyles/data/series.h"
#include "tstyles/scene/camera.h"

namespace tstyles {

using WorldSegment = std::pair<glm::dvec3, glm::dvec3>;

// The coast's segments in display (world) coordinates: each node of the surface stands for the cell
// around it, and an edge between a node without data and one with data is a segment. None for a
// series whose first time-step is not rectilinear or has no missing value at its surface.
std::vector<WorldSegment> coastSegments(const Series& display);

// The segments projected through the view and drawn as lines of `ink`.
void drawCoast(Canvas& canvas, const std::vector<WorldSegment>& segments, const View& view, const glm::vec4& ink);

}  // namespace tstyles
