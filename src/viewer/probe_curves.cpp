// Caching and describing the probes' curves.
#include "probe_curves.h"

#include <array>

#include "tstyles/core/interval.h"
#include "tstyles/data/temporal_probe.h"

namespace tstyles::viewer {

const std::vector<ProbeCurve>& ProbeCurves::update(const std::vector<glm::dvec3>& places,
                                                   const std::shared_ptr<const Series>& series,
                                                   const DisplayFrame& frame) {
    if (places == places_ && series == series_ && frame.rotation == rotation_ && frame.scale == scale_)
        return curves_;
    places_ = places;
    series_ = series;
    rotation_ = frame.rotation;
    scale_ = frame.scale;
    curves_.clear();
    if (!series) return curves_;
    const TemporalProbe probe(*series);
    for (const glm::dvec3& place : places) {
        ProbeCurve curve;
        curve.file = place;
        curve.shown = shownCoordinatesOfFile(*series, frame, place);
        curve.values = probe.valuesAt(curve.shown);
        curves_.push_back(std::move(curve));
    }
    return curves_;
}

glm::vec3 probeColour(std::size_t index) {
    // Saturated, mid-to-light colours: they show on the dark background and beside the time
    // colours' ramps, and differ in hue from one probe to the next.
    static constexpr std::array<glm::vec3, 8> palette{
        glm::vec3{1.00f, 0.82f, 0.16f},  // yellow
        glm::vec3{0.30f, 0.85f, 1.00f},  // sky
        glm::vec3{1.00f, 0.42f, 0.62f},  // pink
        glm::vec3{0.55f, 0.95f, 0.35f},  // lime
        glm::vec3{1.00f, 0.58f, 0.20f},  // orange
        glm::vec3{0.75f, 0.55f, 1.00f},  // violet
        glm::vec3{0.30f, 1.00f, 0.80f},  // aquamarine
        glm::vec3{0.95f, 0.95f, 0.95f},  // white
    };
    return palette[index % palette.size()];
}

std::string placeText(const glm::dvec3& place) {
    return "(" + formatNumber(place.x) + ", " + formatNumber(place.y) + ", " + formatNumber(place.z) + ")";
}

ProbeColumns probeColumns(const std::vector<ProbeCurve>& curves, const Series& series,
                          const std::vector<std::string>& timeLabels) {
    ProbeColumns columns;
    for (const TimeStep& step : series.steps) columns.times.push_back(step.time);
    columns.timeLabels = timeLabels;
    for (std::size_t index = 0; index < curves.size(); ++index) {
        columns.headers.push_back("probe " + std::to_string(index + 1) + " at " + placeText(curves[index].file));
        columns.values.push_back(curves[index].values);
    }
    return columns;
}

}  // namespace tstyles::viewer
