// Several files of one volume each, taken in the given order as the time-steps of one series.
#pragma once

#include <filesystem>
#include <functional>
#include <vector>

#include "source_series.h"
#include "tstyles/data/read_options.h"

namespace tstyles {

using SingleFileReader = std::function<SourceSeries(const std::filesystem::path&, const ReadOptions&)>;

// One file: the reader's own series. Several: each must hold exactly one time-step; their times
// are 0, 1, 2, ... in the order given.
std::function<SourceSeries(const std::vector<std::filesystem::path>&, const ReadOptions&)> stackedFiles(
    SingleFileReader reader);

}  // namespace tstyles
