// From what a reader found to a Series: the step selection, the memory check (refuse, or fit by
// resolution or by step count), resampling, the value range (given or from the data, missing values
// left out) and the mapping to density.
#pragma once

#include "source_series.h"
#include "tstyles/data/read_options.h"

namespace tstyles {

// The series as read, values still raw (missing ones NaN); `valueRange` is the range the density
// mapping will use. `convert` writes this; everything else normalises it with toDensity.
Series assembleRawSeries(const SourceSeries& source, const ReadOptions& options);

// Maps every time-step's raw values to density by the series' value range.
Series toDensity(Series raw);

}  // namespace tstyles
