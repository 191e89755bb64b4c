// The pinned probes' values over time (docs/probe.md): one curve per place of Scene::probes, in
// the data's own unit, each time-step sampled in its own grid (TemporalProbe), recomputed only
// when the places or the series change. GL-free; the panel draws them (probe_panel.h).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/display_frame.h"
#include "tstyles/data/probe_csv.h"
#include "tstyles/data/series.h"

namespace tstyles::viewer {

struct ProbeCurve {
    glm::dvec3 file{0.0};   // as the scene holds it: the file's coordinates
    glm::dvec3 shown{0.0};  // the same in the shown series' (display) coordinates
    std::vector<std::optional<double>> values;  // per time-step; none outside its grid or where it has no data
};

class ProbeCurves {
public:
    // The curves of `places` on `series` (turned for display by `frame`), as last computed when
    // neither changed.
    const std::vector<ProbeCurve>& update(const std::vector<glm::dvec3>& places,
                                          const std::shared_ptr<const Series>& series, const DisplayFrame& frame);

private:
    std::vector<glm::dvec3> places_;
    std::shared_ptr<const Series> series_;
    glm::dmat3 rotation_{1.0};
    glm::dvec3 scale_{1.0};
    std::vector<ProbeCurve> curves_;
};

// A probe's colour on the picture and in the plot: a categorical palette of kMaxProbes colours
// that stay apart from each other and from the time colours' dark and light ends.
glm::vec3 probeColour(std::size_t index);

// "(-95, 40, 500)": a place as `probe --at` takes it.
std::string placeText(const glm::dvec3& place);

// The curves as CSV columns, one per probe headed "probe N at (x, y, z)", with the series' times
// and `timeLabels`.
ProbeColumns probeColumns(const std::vector<ProbeCurve>& curves, const Series& series,
                          const std::vector<std::string>& timeLabels);

}  // namespace tstyles::viewer
