// The value gradient at the visible places of a series, for the boundaries that unchanged places
// keep (UnchangedTime::boundary, docs/automatic-scene.md): where a faint unchanged place lies inside
// a region of one value it fades, where it lies on a boundary between values it stays, so that the
// picture shows surfaces and not a fog. Its parts are public so that processes that each hold one
// block of a series can take their own nodes' magnitudes and gather them (src/distributed).
#pragma once

#include <cstddef>
#include <vector>

#include "tstyles/data/series.h"
#include "tstyles/scene/transfer_function.h"

namespace tstyles {

// The gradient magnitudes (density per display length unit) at every `stride`-th node of a
// rectilinear time-step that the STF shows: central differences one node apart, one-sided at the
// grid's faces and beside missing values. Nothing for other grids.
void addGradientMagnitudes(const TimeStep& step, const Stf& stf, std::size_t stride, std::vector<double>& magnitudes);

// The magnitude at which an unchanged place keeps its whole share of opacity: the 99th percentile of
// `magnitudes` (a boundary as steep as the steepest one in a hundred places); 0 where there are none.
double boundaryGradientOf(std::vector<double> magnitudes);

// Of the series' first time-step, at most about 1 M of its nodes.
std::vector<double> gradientMagnitudes(const Series& series, const Stf& stf);

}  // namespace tstyles
