// Comparison thresholds as JSON objects ({"max_difference": 2, "min_ssim": 0.99, ...}): the keys of
// `tstyles compare --thresholds FILE` and of a `tstyles check` suite (docs/ci.md).
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "tstyles/image/image_comparison.h"

namespace tstyles::cli {

// `base` with the keys of `object` applied. InputError naming `file` and the key (under `field`)
// for an unknown key or a value that is not a number >= 0.
ComparisonThresholds thresholdsFromJson(const nlohmann::json& object, ComparisonThresholds base,
                                        const std::filesystem::path& file, const std::string& field);

// Parses a JSON file, comments allowed; InputError naming it when it cannot be read or parsed.
nlohmann::json readJsonFile(const std::filesystem::path& file);

}  // namespace tstyles::cli
