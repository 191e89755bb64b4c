// Reading comparison thresholds for compare and check.
#include "comparison_thresholds.h"

#include <cmath>
#include <optional>

namespace tstyles::cli {
namespace {

// A threshold: a number >= 0; those counted in whole 1/255 steps are whole (2.5 would silently act as 2).
std::optional<double> threshold(const JsonField& thresholds, const char* key, bool wholeSteps) {
    const std::optional<JsonField> field = thresholds.optionalMember(key);
    if (!field) return std::nullopt;
    const double number = field->finiteNumber();
    if (!(number >= 0.0)) field->fail("must be >= 0");
    if (wholeSteps && number != std::floor(number)) field->fail("must be a whole number of 1/255 steps");
    return number;
}

}  // namespace

ComparisonThresholds thresholdsFromJson(const JsonField& thresholds, ComparisonThresholds base) {
    thresholds.allowOnlyKeys({"max_difference", "pixel_threshold", "max_failing_share", "max_mean", "min_ssim"});
    if (const auto maxDifference = threshold(thresholds, "max_difference", true)) base.maxDelta = int(*maxDifference);
    if (const auto pixel = threshold(thresholds, "pixel_threshold", true)) base.pixelThreshold = int(*pixel);
    if (const auto share = threshold(thresholds, "max_failing_share", false)) {
        if (*share > 100.0) thresholds.member("max_failing_share").fail("is a percentage, <= 100");
        base.maxFailingFraction = *share / 100.0;
    }
    if (const auto mean = threshold(thresholds, "max_mean", false)) base.maxMeanDelta = *mean;
    if (const auto ssim = threshold(thresholds, "min_ssim", false)) {
        if (*ssim > 1.0) thresholds.member("min_ssim").fail("must be <= 1 (SSIM of identical images)");
        base.minSsim = *ssim;
    }
    return base;
}

}  // namespace tstyles::cli
