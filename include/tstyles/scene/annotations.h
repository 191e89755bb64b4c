// What a rendered picture explains about itself: a legend of the transfer functions in use, a title,
// a caption (compositor, time-steps, time range), the series' box with labelled ticks and a scale
// bar. Scene data only; the annotate module draws them (format: docs/annotations.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace tstyles {

enum class Corner { TopLeft, TopRight, BottomLeft, BottomRight };
std::string toString(Corner corner);  // "top-left", ...
std::optional<Corner> cornerFromString(const std::string& name);
std::vector<std::string> cornerNames();

struct Annotations {
    bool legend = false;
    Corner legendCorner = Corner::TopRight;
    std::string title;     // empty: no title
    bool caption = false;  // the compositor, the exposed time-steps and their time range
    bool box = false;      // the series' bounding box with ticks in the data's units
    bool scaleBar = false;
    // A map's coast: the edge between the surface's missing values (land) and its data, drawn at
    // the surface (src/annotate/coastline.h).
    bool coast = false;
    // Text height in pixels on a 512-pixel-high image; larger and smaller images scale it.
    double fontSize = 13.0;
    bool operator==(const Annotations&) const = default;
    bool any() const { return legend || !title.empty() || caption || box || scaleBar || coast; }
};

}  // namespace tstyles
