// Even or uneven: one rule for every reader that gets an axis as coordinates.
#include "tstyles/data/axis_nodes.h"

#include <cmath>

namespace tstyles {

AxisNodes axisNodesOf(const std::vector<double>& increasing, double relativeTolerance) {
    AxisNodes nodes;
    nodes.origin = increasing.front();
    nodes.spacing = (increasing.back() - increasing.front()) / double(increasing.size() - 1);
    bool even = true;
    for (std::size_t index = 1; index < increasing.size(); ++index)
        even = even && std::abs((increasing[index] - increasing[index - 1]) - nodes.spacing) <=
                           relativeTolerance * nodes.spacing;
    if (!even)
        for (double value : increasing) nodes.positions.push_back(value - increasing.front());
    return nodes;
}

}  // namespace tstyles
