// From what a reader found to a Series: the step selection, the memory check (refuse, or fit by
// resolution or by step count), resampling, the value range (given or from the data, missing values
// left out) and the mapping to density.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "source_series.h"
#include "tstyles/data/read_options.h"

namespace tstyles {

// Most time-steps a series may declare: each becomes a description in memory and a row of the
// GPU's tables long before any value is read.
inline constexpr std::uint64_t kMaxTimeSteps = std::uint64_t(1) << 20;

// Refuses a time-step count read from a file (`field` names it) above kMaxTimeSteps, or whose
// descriptions alone would not fit in half of the machine's memory, before anything is allocated
// for them. (--max-memory counts the values; the few steps it selects are checked there.)
void requireStepCount(const std::filesystem::path& file, const std::string& field, std::uint64_t count);

// The series as read, values still raw (missing ones NaN); `valueRange` is the range the density
// mapping will use. `convert` writes this; everything else normalises it with toDensity.
Series assembleRawSeries(const SourceSeries& source, const ReadOptions& options);

// Maps every time-step's raw values to density by the series' value range.
Series toDensity(Series raw);

}  // namespace tstyles
