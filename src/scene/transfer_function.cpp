// Evaluation of piecewise-linear transfer functions, and the defaults a scene starts from.
#include "tstyles/scene/transfer_function.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace tstyles {
namespace {

bool byPosition(const auto& a, const auto& b) { return a.at < b.at; }

// Reads a curve given by nodes sorted by `at`. Two nodes at the same position make a step: at
// exactly that position the later node wins, so the value just after the step is the one shown.
template <typename Node, typename ValueOf>
auto evaluateSorted(const std::vector<Node>& nodes, double x, ValueOf valueOf) {
    if (std::isnan(x) || x < nodes.front().at) return valueOf(nodes.front());
    if (x >= nodes.back().at) return valueOf(nodes.back());
    // First node strictly after x; x lies in [nodes[i-1].at, nodes[i].at) with a positive gap.
    const auto after = std::upper_bound(nodes.begin(), nodes.end(), x,
                                        [](double value, const Node& node) { return value < node.at; });
    const Node& left = *std::prev(after);
    const Node& right = *after;
    const double t = (x - left.at) / (right.at - left.at);
    return valueOf(left) + t * (valueOf(right) - valueOf(left));
}

// The renderer and the reader keep nodes sorted, but a curve built by hand may not be; sorting a
// copy keeps evaluate() const and correct either way.
template <typename Node, typename ValueOf>
auto evaluateNodes(const std::vector<Node>& nodes, double x, ValueOf valueOf) {
    if (std::is_sorted(nodes.begin(), nodes.end(), byPosition<Node, Node>)) {
        return evaluateSorted(nodes, x, valueOf);
    }
    std::vector<Node> sorted = nodes;
    std::stable_sort(sorted.begin(), sorted.end(), byPosition<Node, Node>);
    return evaluateSorted(sorted, x, valueOf);
}

}  // namespace

ColorOpacity TransferFunction1D::evaluate(double x) const {
    ColorOpacity result;
    result.opacity =
        opacity.empty() ? 0.0 : evaluateNodes(opacity, x, [](const OpacityNode& n) { return n.opacity; });
    result.color =
        color.empty() ? glm::dvec3(1.0) : evaluateNodes(color, x, [](const ColorNode& n) { return n.color; });
    return result;
}

void TransferFunction1D::sortNodes() {
    // Stable, so that the two nodes of a step keep the order that says which side is which.
    std::stable_sort(opacity.begin(), opacity.end(), byPosition<OpacityNode, OpacityNode>);
    std::stable_sort(color.begin(), color.end(), byPosition<ColorNode, ColorNode>);
}

double GradientTstf::normalize(double change) const {
    // The scene reader insists on low < high; a hand-built empty range degrades to a step.
    if (!(rangeHigh > rangeLow)) return change >= rangeHigh ? 1.0 : 0.0;
    return std::clamp((change - rangeLow) / (rangeHigh - rangeLow), 0.0, 1.0);
}

Stf defaultStf() {
    Stf stf;
    stf.curve.opacity = {{0.0, 0.0}, {1.0, 1.0}};
    stf.curve.color = {{0.0, glm::dvec3(1.0)}};
    return stf;
}

IndexTstf defaultIndexTstf() {
    IndexTstf tstf;
    tstf.curve.opacity = {{0.0, 1.0}};
    tstf.curve.color = {{0.0, glm::dvec3(1.0)}};
    return tstf;
}

GradientTstf defaultGradientTstf() {
    GradientTstf tstf;
    tstf.curve.opacity = {{0.0, 1.0}};
    tstf.curve.color = {{0.0, glm::dvec3(1.0)}};
    return tstf;
}

}  // namespace tstyles
