// The node coordinates of one grid axis as a RectilinearGrid holds them: the first node, the mean
// gap, and the positions where the gaps are not even (a NetCDF file's depth levels, a VTK
// RectilinearGrid's coordinates).
#pragma once

#include <vector>

namespace tstyles {

struct AxisNodes {
    double origin = 0.0;
    double spacing = 1.0;            // the mean gap: (last - first) / (count - 1)
    std::vector<double> positions;   // empty when even; else each node's distance from the first
};

// `increasing`: at least 2 strictly increasing values. The axis is even when every gap is within
// `relativeTolerance` times the mean gap of it.
AxisNodes axisNodesOf(const std::vector<double>& increasing, double relativeTolerance);

}  // namespace tstyles
