// The probe panel under the picture (docs/probe.md): each pinned place's values over time as a
// curve in its probe's colour, against the time axis with the slider's labels; each point in its
// time-step's TSTF colour, gaps where a time-step has no value there, the values the STF shows
// shaded. Hovering a point names its value; each probe can be removed; the curves export as CSV.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "probe_curves.h"
#include "tstyles/data/series.h"
#include "tstyles/scene/scene.h"
#include "ui_anchors.h"
#include "ui_geometry.h"

namespace tstyles::viewer {

struct ProbePanelState {
    const std::vector<ProbeCurve>& curves;
    const Series& series;
    const Scene& scene;
    const std::vector<std::string>& timeLabels;
    int currentStep = 0;  // the slider's time-step, marked on the time axis
};

// What the user asked of the panel this frame.
struct ProbePanelRequests {
    std::optional<std::size_t> remove;  // the probe's index
    bool clear = false;
    bool exportCsv = false;
};

ProbePanelRequests drawProbePanel(const ScreenRect& rect, const ProbePanelState& state, UiAnchors& anchors);

// The values the STF shows (opacity above 0) in the data's unit: the lowest and highest density it
// shows, mapped through the series' value range; none where it shows nothing.
std::optional<std::pair<double, double>> stfShownValues(const Stf& stf, const Series& series);

}  // namespace tstyles::viewer
