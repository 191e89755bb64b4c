// Keeping a series read from a scientist's file in our manifest form (`tstyles convert`): the raw
// values as float32 (missing ones NaN, declared as the manifest's missing_value), written into a
// temporary folder that is renamed into place only when complete.
#pragma once

#include <filesystem>

#include "tstyles/data/manifest.h"
#include "tstyles/data/series.h"

namespace tstyles {

// A series whose values are still raw (openRawSeries) as the manifest writer takes it. Times that
// do not increase are an InputError naming `source` (a manifest needs increasing times).
RawSeries toRawSeries(const Series& rawValues, const std::filesystem::path& source);

// Writes the series to `directory` (series.json and its files) through a temporary sibling folder
// and a rename. An existing non-empty `directory` is an InputError unless `overwrite`, which
// replaces it only once the new folder is complete. A failure leaves nothing behind.
void writeSeriesFolder(const RawSeries& series, const std::filesystem::path& directory, bool overwrite);

}  // namespace tstyles
