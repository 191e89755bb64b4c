// A probe's values as a picture (docs/probe.md): one place's values over time as a line plot
// (time across, value up), or a line of places as a Hovmoeller diagram (distance across, time
// down, a colour per value, with a colour bar). Axes with ticks and labels; missing values are
// gaps in the curve and grey cells in the diagram. CPU only (Canvas, Font).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/image/image.h"

namespace tstyles {

struct ProbeTable {
    std::string title;                    // what and where: "clwc at (-95, 40, -500)"
    std::string unit;                     // the values' unit; empty: none
    std::vector<double> times;            // one per time-step
    std::vector<std::string> timeLabels;  // as the slider writes them
    std::vector<double> distances;        // along the line from its start; one place: {0}
    std::vector<std::vector<std::optional<double>>> values;  // per place, per time-step
    // A line plot's marker colour per time-step: the index TSTF's, as the picture colours time.
    // Empty: the curve's colour.
    std::vector<glm::vec3> timeColours;
};

// The colour the diagram gives a value at `fraction` of the values' range (0 lowest, 1 highest): a
// ramp from dark blue through teal and green to yellow, light rising throughout.
glm::vec3 probeRampColour(double fraction);

// The picture of `table` at `size` pixels: a line plot for one place, a Hovmoeller diagram for
// several. Premultiplied RGBA, opaque.
Image drawProbePlot(const ProbeTable& table, glm::ivec2 size);

}  // namespace tstyles
