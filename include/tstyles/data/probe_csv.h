// Probed values as CSV, for `tstyles probe --csv` and the window's probe export (docs/probe.md): a
// header "time,label,<a column per place>", then a row per time-step: the time as a number, its
// label as the slider writes it, and each place's value at the precision the series holds it
// (float32), empty where it is missing.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace tstyles {

struct ProbeColumns {
    std::vector<double> times;            // one per time-step
    std::vector<std::string> timeLabels;  // one per time-step
    std::vector<std::string> headers;     // one per place
    std::vector<std::vector<std::optional<double>>> values;  // per place, per time-step
};

void writeProbeCsv(std::ostream& out, const ProbeColumns& columns);

// A value as the series holds it: its densities are float32, so a value has about 7 significant
// digits, written shortest at that precision (12, not 12.000000085681677).
std::string storedValueText(double value);

}  // namespace tstyles
