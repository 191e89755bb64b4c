// The changes over time of a series' visible places (temporal_change.h).
#include "tstyles/scene/temporal_change.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "tstyles/data/density_sampling.h"
#include "tstyles/scene/visible_bounds.h"

namespace tstyles {
namespace {

// The percentile of the visible voxels' temporal change that the gradient TSTF's range reaches.
constexpr double kChangePercentile = 0.99;
// A lattice of this many points per axis samples the change of series whose time-steps do not share
// one grid.
constexpr int kChangeLattice = 32;
// A shared grid's changes are taken at this many nodes at most.
constexpr std::size_t kMostChangedNodes = std::size_t(1) << 20;
// A place is unchanged below this share of the typical largest change, where noise asks no more.
constexpr double kUnchangedShareOfChange = 0.1;
// The noise-only range that a place exceeds this rarely is not called a change.
constexpr double kNoiseRangeProbability = 0.01;
// The median absolute k-th differences of independent Gaussian noise of standard deviation 1, k = 1
// to 4: the median of |N(0, C(2k, k))|, 0.67449 times sqrt 2, sqrt 6, sqrt 20 and sqrt 70.
constexpr std::array<double, 4> kMedianDifference = {0.953873, 1.652097, 3.016418, 5.643163};
// The third and fourth differences are taken where they leave this many values (monthly series of
// a year and longer): a season's curvature, which the second differences still see, fades in them.
constexpr std::size_t kFewestHigherDifferences = 8;
// The changing places' opacity gain is at most this.
constexpr double kMostGain = 8.0;

double medianOf(std::vector<double> values) {
    const std::size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(middle), values.end());
    const double upper = values[middle];
    if (values.size() % 2 == 1) return upper;
    return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + std::ptrdiff_t(middle)));
}

double standardNormalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// P(range of `count` independent standard normal values <= r): count * integral of
// phi(x) (Phi(x + r) - Phi(x))^(count - 1) dx (the lowest value at x, the others within r above it).
double rangeCdf(double r, std::size_t count) {
    constexpr double kFrom = -9.0, kTo = 9.0, kStep = 0.01;
    double sum = 0.0;
    for (double x = kFrom; x <= kTo; x += kStep) {
        const double density = std::exp(-0.5 * x * x) / std::sqrt(2.0 * M_PI);
        sum += density * std::pow(standardNormalCdf(x + r) - standardNormalCdf(x), double(count - 1));
    }
    return double(count) * sum * kStep;
}

}  // namespace

bool sharesOneGrid(const Series& series) {
    if (series.steps.empty()) return false;
    const TimeStep& first = series.steps.front();
    if (!std::holds_alternative<RectilinearGrid>(first.grid)) return false;
    return std::all_of(series.steps.begin(), series.steps.end(), [&](const TimeStep& step) {
        return std::holds_alternative<RectilinearGrid>(step.grid) && step.dims() == first.dims() &&
               step.placement == first.placement;
    });
}

std::size_t changeNodeStride(const Series& series) {
    const std::size_t nodes = series.steps.empty() ? 0 : gridVoxelCount(series.steps.front().grid);
    return std::max<std::size_t>(1, nodes / kMostChangedNodes);
}

std::vector<glm::dvec3> changeLatticePoints(const Bounds& visible) {
    std::vector<glm::dvec3> points;
    points.reserve(std::size_t(kChangeLattice) * kChangeLattice * kChangeLattice);
    for (int k = 0; k < kChangeLattice; ++k)
        for (int j = 0; j < kChangeLattice; ++j)
            for (int i = 0; i < kChangeLattice; ++i)
                points.push_back(visible.lower + (glm::dvec3(i, j, k) + 0.5) / double(kChangeLattice) * visible.size());
    return points;
}

double noiseOfPlace(const std::vector<double>& densities) {
    if (densities.size() < 2) return 0.0;
    double noise = std::numeric_limits<double>::infinity();
    std::vector<double> differences = densities;
    for (std::size_t order = 1; order <= kMedianDifference.size() && differences.size() >= 2; ++order) {
        for (std::size_t index = 0; index + 1 < differences.size(); ++index)
            differences[index] = differences[index + 1] - differences[index];
        differences.pop_back();
        if (order > 2 && differences.size() < kFewestHigherDifferences) break;
        std::vector<double> magnitudes(differences.size());
        std::transform(differences.begin(), differences.end(), magnitudes.begin(),
                       [](double difference) { return std::abs(difference); });
        noise = std::min(noise, medianOf(std::move(magnitudes)) / kMedianDifference[order - 1]);
    }
    return noise;
}

void addChange(const std::vector<double>& densities, const Stf& stf, PlaceChanges& places) {
    std::vector<double> valid;
    valid.reserve(densities.size());
    std::size_t visible = 0;
    for (double density : densities) {
        if (isMissing(float(density))) continue;
        valid.push_back(density);
        visible += stf.curve.evaluate(density).opacity > 0.0 ? 1 : 0;
    }
    if (visible == 0 || valid.size() < 2) return;
    const auto [lowest, highest] = std::minmax_element(valid.begin(), valid.end());
    places.changes.push_back(*highest - *lowest);
    // The noise of what is seen: a place of the transparent background that noise lifts into the STF
    // now and then is not (its quieter noise would lower the estimate).
    if (2 * visible >= valid.size()) {
        places.noises.push_back(noiseOfPlace(valid));
        places.noiseDensities.push_back(std::accumulate(valid.begin(), valid.end(), 0.0) / double(valid.size()));
    }
}

double typicalOf(std::vector<double> changes) {
    if (changes.empty()) return 1.0;
    const auto at = changes.begin() + std::ptrdiff_t(kChangePercentile * double(changes.size() - 1));
    std::nth_element(changes.begin(), at, changes.end());
    return std::clamp(*at, 1e-3, 1.0);
}

double noiseRangeQuantile(std::size_t count) {
    if (count < 2) return 0.0;
    double low = 0.0, high = 12.0;
    for (int iteration = 0; iteration < 40; ++iteration) {
        const double middle = 0.5 * (low + high);
        (rangeCdf(middle, count) < 1.0 - kNoiseRangeProbability ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

int unchangedDensityBand(double density) {
    return std::clamp(int(density * kUnchangedDensityBands), 0, kUnchangedDensityBands - 1);
}

UnchangedFit unchangedFitOf(const PlaceChanges& places, std::size_t stepCount) {
    const double share = kUnchangedShareOfChange * typicalOf(places.changes);
    const double rangeQuantile = noiseRangeQuantile(stepCount);
    const double tieQuantile = noiseRangeQuantile(2);
    const double noise = places.noises.empty() ? 0.0 : medianOf(places.noises);
    UnchangedFit fit;
    fit.below = std::clamp(std::max(share, noise * rangeQuantile), 0.0, 1.0);
    fit.tie = std::clamp(noise * tieQuantile, 0.0, 1.0);
    std::vector<std::vector<double>> bandNoises(kUnchangedDensityBands);
    for (std::size_t place = 0; place < places.noises.size(); ++place)
        bandNoises[std::size_t(unchangedDensityBand(places.noiseDensities[place]))].push_back(places.noises[place]);
    for (std::vector<double>& band : bandNoises) {
        const bool ownNoise = stepCount >= kFewestStepsForBands && band.size() >= kFewestPlacesPerBand;
        const double bandNoise = ownNoise ? medianOf(std::move(band)) : noise;
        fit.belowByDensity.push_back(std::clamp(std::max(share, bandNoise * rangeQuantile), 0.0, 1.0));
        fit.tieByDensity.push_back(std::clamp(bandNoise * tieQuantile, 0.0, 1.0));
    }
    const auto changing = std::count_if(places.changes.begin(), places.changes.end(),
                                        [&](double change) { return change > fit.below; });
    if (changing > 0)
        fit.gain = std::clamp(std::cbrt(double(places.changes.size()) / double(changing)), 1.0, kMostGain);
    return fit;
}

void takeFit(UnchangedTime& unchanged, const UnchangedFit& fit) {
    unchanged.below = fit.below;
    unchanged.tie = fit.tie;
    unchanged.gain = fit.gain;
    unchanged.boundary = fit.boundary;
    unchanged.belowByDensity = fit.belowByDensity;
    unchanged.tieByDensity = fit.tieByDensity;
}

UnchangedFit fittedOf(const UnchangedTime& unchanged) {
    return {unchanged.below,    unchanged.tie,           unchanged.gain,
            unchanged.boundary, unchanged.belowByDensity, unchanged.tieByDensity};
}

PlaceChanges temporalChanges(const Series& series, const Stf& stf) {
    PlaceChanges changes;
    if (series.size() < 2) return changes;
    std::vector<double> densities(series.size());
    if (sharesOneGrid(series)) {
        const std::size_t voxels = series.steps.front().density.size();
        const std::size_t stride = changeNodeStride(series);
        for (std::size_t voxel = 0; voxel < voxels; voxel += stride) {
            for (std::size_t step = 0; step < series.size(); ++step)
                densities[step] = series.steps[step].density[voxel];
            addChange(densities, stf, changes);
        }
        return changes;
    }
    const TemporalProfiler profiler(series);
    for (const glm::dvec3& at : changeLatticePoints(visibleBounds(series, stf))) {
        densities.clear();
        for (const auto& density : profiler.profile(at))
            if (density) densities.push_back(*density);
        addChange(densities, stf, changes);
    }
    return changes;
}

}  // namespace tstyles
