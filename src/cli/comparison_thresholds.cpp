// Reading comparison thresholds and small JSON files for compare and check.
#include "comparison_thresholds.h"

#include <cmath>
#include <fstream>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"

namespace tstyles::cli {

nlohmann::json readJsonFile(const std::filesystem::path& file) {
    // A FIFO would block the read: only a regular file is opened.
    if (userPathKind({}, file) != PathKind::Missing) requireUserFile({}, file, "JSON file");
    std::ifstream in(file);
    if (!in) throwInputError(file, "", "cannot open it");
    try {
        return nlohmann::json::parse(in, nullptr, true, true);
    } catch (const nlohmann::json::exception& error) {
        std::string detail = error.what();
        if (const auto end = detail.find("] "); end != std::string::npos) detail.erase(0, end + 2);
        throwInputError(file, "", "not valid JSON: " + detail);
    }
}

ComparisonThresholds thresholdsFromJson(const nlohmann::json& object, ComparisonThresholds base,
                                        const std::filesystem::path& file, const std::string& field) {
    const auto keyPath = [&](const std::string& key) { return field.empty() ? key : field + "." + key; };
    if (!object.is_object()) throwInputError(file, field, "expected an object of thresholds");
    for (const auto& [key, value] : object.items()) {
        if (!value.is_number()) throwInputError(file, keyPath(key), "expected a number");
        const double number = value.get<double>();
        if (!(number >= 0.0)) throwInputError(file, keyPath(key), "must be >= 0");
        // Differences are whole 1/255 steps; 2.5 would silently act as 2.
        if ((key == "max_difference" || key == "pixel_threshold") && number != std::floor(number))
            throwInputError(file, keyPath(key), "must be a whole number of 1/255 steps");
        if (key == "max_failing_share" && number > 100.0) throwInputError(file, keyPath(key), "is a percentage, <= 100");
        if (key == "min_ssim" && number > 1.0) throwInputError(file, keyPath(key), "must be <= 1 (SSIM of identical images)");
        if (key == "max_difference") base.maxDelta = int(number);
        else if (key == "pixel_threshold") base.pixelThreshold = int(number);
        else if (key == "max_failing_share") base.maxFailingFraction = number / 100.0;
        else if (key == "max_mean") base.maxMeanDelta = number;
        else if (key == "min_ssim") base.minSsim = number;
        else
            throwInputError(file, keyPath(key), "unknown key; allowed: max_difference, pixel_threshold, "
                                                "max_failing_share, max_mean, min_ssim");
    }
    return base;
}

}  // namespace tstyles::cli
