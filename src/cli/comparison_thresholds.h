// Comparison thresholds as JSON objects ({"max_difference": 2, "min_ssim": 0.99, ...}): the keys of
// `tstyles compare --thresholds FILE` and of a `tstyles check` suite (docs/ci.md).
#pragma once

#include "tstyles/core/json_field.h"
#include "tstyles/image/image_comparison.h"

namespace tstyles::cli {

// `base` with the keys of `thresholds` applied. InputError naming the file and the key for an
// unknown key or a value that is not a number >= 0.
ComparisonThresholds thresholdsFromJson(const JsonField& thresholds, ComparisonThresholds base);

}  // namespace tstyles::cli
