// Plot3D as the opener sees it: the chosen block's structured grid, one time-step per solution (or
// function) file, each file read when its step is. The layout checks happen when it is opened.
#pragma once

#include "../source_series.h"
#include "tstyles/data/plot3d.h"

namespace tstyles {

SourceSeries openPlot3DSource(const Plot3DOptions& options);

// Whether a file is laid out like a binary Plot3D grid file (the content sniff of the format table).
bool looksLikePlot3DGrid(const std::filesystem::path& file);

}  // namespace tstyles
