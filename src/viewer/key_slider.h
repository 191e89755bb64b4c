// A slider for a numeric scene key (scene_keys.h): its range comes from the key's line, narrowed to
// `shown` where the line's range is open or too wide to drag through, and its tooltip is the line's
// text, so the window offers only values a scene file may hold and says what they mean.
#pragma once

#include <optional>
#include <string_view>

#include "tstyles/core/json_field.h"

namespace tstyles::viewer {

struct KeySlider {
    const char* label;
    std::string_view keyPath;            // "raycast.termination"
    const char* format = "%.3f";
    bool logarithmic = false;
    std::optional<Interval> shown;       // inside the key's range; none: the key's range
    const char* tooltipDetail = nullptr;  // said after the key's text (what "auto" fits, ...)
};

// Returns whether the value changed. std::logic_error for a key the table lacks, or for `shown`
// reaching outside the key's range (a window that would write what the reader refuses).
bool drawKeySlider(const KeySlider& slider, double& value);

}  // namespace tstyles::viewer
