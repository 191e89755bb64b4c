// Background peak and percentile window of the density histogram (automatic_opacity.h).
#include "tstyles/scene/automatic_opacity.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tstyles {
namespace {

constexpr int kBins = kOpacityHistogramBins;
// At most this many values are counted; larger series are subsampled with a regular stride.
constexpr std::size_t kMostCountedValues = std::size_t(1) << 23;
// A peak that holds this share of all values within kPeakHalfWidth bins of its top is a background
// (air, zeros around a scan), not a feature; the width lets noise spread it (CT air at -1000 +- 10).
constexpr double kBackgroundShare = 0.2;
constexpr int kPeakHalfWidth = 5;
// The background peak extends over its neighbours down to this share of its top bin.
constexpr double kPeakShoulder = 0.02;
constexpr double kLowPercentile = 0.05;
constexpr double kHighPercentile = 0.99;
// A ray through the visible part of a time-step should gather about this much opacity.
constexpr double kTargetRayOpacity = 0.95;

double binCentre(int bin) { return (double(bin) + 0.5) / kBins; }

std::size_t totalVoxels(const Series& series) {
    std::size_t total = 0;
    for (const TimeStep& step : series.steps) total += gridVoxelCount(step.grid);
    return total;
}

// The density below which `fraction` of the counted values lie.
double percentile(const std::vector<double>& counts, double total, double fraction) {
    double below = 0.0;
    for (int bin = 0; bin < kBins; ++bin) {
        below += counts[std::size_t(bin)];
        if (below >= fraction * total) return binCentre(bin);
    }
    return 1.0;
}

}  // namespace

int opacityHistogramBin(float density) { return std::clamp(int(density * kBins), 0, kBins - 1); }

std::size_t opacityHistogramStride(const Series& series) {
    return std::max<std::size_t>(1, totalVoxels(series) / kMostCountedValues);
}

std::size_t averageVoxelsPerStep(const Series& series) {
    return series.steps.empty() ? 0 : totalVoxels(series) / series.steps.size();
}

OpacityWindow automaticOpacityWindow(const Series& series) {
    const std::size_t stride = opacityHistogramStride(series);
    std::vector<double> counts(kBins, 0.0);
    for (const TimeStep& step : series.steps)
        for (std::size_t index = 0; index < step.density.size(); index += stride) {
            const float density = step.density[index];
            if (!isMissing(density)) counts[std::size_t(opacityHistogramBin(density))] += 1.0;
        }
    return opacityWindowOf(std::move(counts), averageVoxelsPerStep(series));
}

OpacityWindow opacityWindowOf(std::vector<double> counts, std::size_t voxelsPerStep) {
    OpacityWindow window;
    const double total = std::accumulate(counts.begin(), counts.end(), 0.0);
    if (total == 0.0) return window;

    std::vector<double> nearby(kBins, 0.0);
    for (int bin = 0; bin < kBins; ++bin)
        for (int other = std::max(0, bin - kPeakHalfWidth); other <= std::min(kBins - 1, bin + kPeakHalfWidth); ++other)
            nearby[std::size_t(bin)] += counts[std::size_t(other)];
    const int top = int(std::max_element(nearby.begin(), nearby.end()) - nearby.begin());
    if (nearby[std::size_t(top)] >= kBackgroundShare * total) {
        int first = std::max(0, top - kPeakHalfWidth);
        int last = std::min(kBins - 1, top + kPeakHalfWidth);
        const double shoulder =
            kPeakShoulder * *std::max_element(counts.begin() + first, counts.begin() + last + 1);
        while (first > 0 && counts[std::size_t(first - 1)] >= shoulder && counts[std::size_t(first - 1)] <= counts[std::size_t(first)]) --first;
        while (last + 1 < kBins && counts[std::size_t(last + 1)] >= shoulder && counts[std::size_t(last + 1)] <= counts[std::size_t(last)]) ++last;
        window.background = {double(first) / kBins, double(last + 1) / kBins};
        double inPeak = 0.0;
        for (int bin = first; bin <= last; ++bin) {
            inPeak += counts[std::size_t(bin)];
            counts[std::size_t(bin)] = 0.0;
        }
        window.backgroundFraction = inPeak / total;
    }
    const double rest = total - window.backgroundFraction * total;
    if (rest > 0.0) {
        window.low = percentile(counts, rest, kLowPercentile);
        // A window at least a bin wide, inside [0, 1] (one value everywhere fills the top bin).
        window.high = std::min(1.0, std::max(percentile(counts, rest, kHighPercentile), window.low + 1.0 / kBins));
        window.low = std::min(window.low, window.high - 1.0 / kBins);
    }
    // A ray crosses about the cube root of the visible voxels; spread the target opacity over them.
    // The ramp averages about half its peak, hence the factor 2.
    const double visibleVoxels = std::max(1.0, (1.0 - window.backgroundFraction) * double(voxelsPerStep));
    const double voxelsAlongRay = std::max(1.0, std::cbrt(visibleVoxels));
    const double perVoxel = 1.0 - std::pow(1.0 - kTargetRayOpacity, 1.0 / voxelsAlongRay);
    window.peak = std::clamp(2.0 * perVoxel, 0.02, 1.0);
    return window;
}

std::vector<OpacityNode> opacityNodes(const OpacityWindow& window) {
    auto ramp = [&](double density) {
        return window.peak * std::clamp((density - window.low) / (window.high - window.low), 0.0, 1.0);
    };
    std::vector<OpacityNode> nodes{{window.low, 0.0}, {window.high, window.peak}};
    if (window.background) {
        const auto [from, to] = *window.background;
        // The peak is transparent wherever it lies: a step down at its start, back up at its end.
        if (to > window.low && from < 1.0) {
            nodes.push_back({from, ramp(from)});
            nodes.push_back({from, 0.0});
            nodes.push_back({to, 0.0});
            if (to < 1.0) nodes.push_back({to, ramp(to)});
        }
    }
    std::stable_sort(nodes.begin(), nodes.end(), [](const OpacityNode& a, const OpacityNode& b) { return a.at < b.at; });
    return nodes;
}

}  // namespace tstyles
