// `tstyles compare EXPECTED ACTUAL`: two images against stated thresholds (docs/ci.md): the figures,
// the worst pixels, a heat map and a side-by-side picture; exit 0 within, 1 beyond, 2 bad input.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "comparison_thresholds.h"
#include "tstyles/core/json_text.h"
#include "tstyles/core/errors.h"
#include "tstyles/image/image_comparison.h"
#include "tstyles/image/image_io.h"

namespace tstyles::cli {
namespace {

struct CompareOptions {
    std::filesystem::path expected;
    std::filesystem::path actual;
    std::optional<std::filesystem::path> thresholdsFile;
    std::optional<int> maxDelta;
    std::optional<int> pixelThreshold;
    std::optional<double> maxFailingShare;  // percent
    std::optional<double> maxMean;
    std::optional<double> minSsim;
    std::optional<std::filesystem::path> diff;
    std::optional<std::filesystem::path> sideBySide;
};

ComparisonThresholds thresholdsOf(const CompareOptions& options) {
    ComparisonThresholds thresholds;
    if (options.thresholdsFile) {
        const nlohmann::json document = readJsonFile(*options.thresholdsFile, "thresholds file", JsonComments::Allowed);
        thresholds = thresholdsFromJson(JsonField(*options.thresholdsFile, document, ""), thresholds);
    }
    if (options.maxDelta) thresholds.maxDelta = *options.maxDelta;
    if (options.pixelThreshold) thresholds.pixelThreshold = *options.pixelThreshold;
    if (options.maxFailingShare) thresholds.maxFailingFraction = *options.maxFailingShare / 100.0;
    if (options.maxMean) thresholds.maxMeanDelta = *options.maxMean;
    if (options.minSsim) thresholds.minSsim = *options.minSsim;
    return thresholds;
}

// A stored value as the 8-bit files show it, so a reader can find the pixel in an image viewer.
std::string bytesOf(const glm::vec4& value) {
    std::ostringstream text;
    for (int c = 0; c < 4; ++c)
        text << (c == 0 ? "" : " ") << std::setw(3) << std::lround(std::clamp(value[c], 0.0f, 1.0f) * 255.0f);
    return text.str();
}

void printFigures(const ImageDifference& difference, const ComparisonThresholds& thresholds) {
    std::cout << "max difference   " << difference.maxDelta << "/255 (R " << difference.maxChannelDelta[0] << ", G "
              << difference.maxChannelDelta[1] << ", B " << difference.maxChannelDelta[2] << ", A "
              << difference.maxChannelDelta[3] << ")   limit " << thresholds.maxDelta << "\n"
              << "pixels beyond " << thresholds.pixelThreshold << "  " << 100.0 * difference.failingFraction
              << " %   limit " << 100.0 * thresholds.maxFailingFraction << " %\n"
              << "mean difference  " << difference.meanDelta << "/255   limit " << thresholds.maxMeanDelta << "\n"
              << "SSIM             " << difference.ssim << "   limit " << thresholds.minSsim << "\n";
    if (difference.worstPixels.empty()) return;
    std::cout << "worst pixels     x     y  diff  expected RGBA     actual RGBA\n";
    for (const WorstPixel& worst : difference.worstPixels)
        std::cout << "             " << std::setw(5) << worst.position.x << " " << std::setw(5) << worst.position.y << " "
                  << std::setw(5) << worst.delta << "  " << bytesOf(worst.expected) << "   " << bytesOf(worst.actual)
                  << "\n";
}

int runCompare(const CompareOptions& options) {
    const ComparisonThresholds thresholds = thresholdsOf(options);
    if (options.diff) requireWritableImagePath(*options.diff, "--diff");
    if (options.sideBySide) requireWritableImagePath(*options.sideBySide, "--side-by-side");
    const Image expected = readImage(options.expected);
    const Image actual = readImage(options.actual);
    if (expected.width != actual.width || expected.height != actual.height)
        throwInputError(options.actual, "",
                        "is " + std::to_string(actual.width) + "x" + std::to_string(actual.height) + " but " +
                            options.expected.string() + " is " + std::to_string(expected.width) + "x" +
                            std::to_string(expected.height) + "; images of different sizes cannot be compared");
    const ImageDifference difference = compareImages(actual, expected, thresholds.pixelThreshold);
    printFigures(difference, thresholds);
    const Image heat = differenceHeatMap(actual, expected, std::max(8, difference.maxDelta));
    if (options.diff) writeImage(heat, *options.diff);
    if (options.sideBySide) writeImage(sideBySide(expected, actual, heat), *options.sideBySide);
    const std::vector<std::string> exceeded = thresholdsExceeded(difference, thresholds);
    if (exceeded.empty()) {
        std::cout << "within the thresholds\n";
        return kExitSuccess;
    }
    for (const std::string& line : exceeded) std::cout << "BEYOND: " << line << "\n";
    return kExitFailure;
}

}  // namespace

Command addCompareCommand(CLI::App& app) {
    auto options = std::make_shared<CompareOptions>();
    CLI::App* command = app.add_subcommand(
        "compare", "Compare two images against thresholds (exit 0 within, 1 beyond, 2 bad input); docs/ci.md");
    command->add_option("expected", options->expected, "The reference image (any format OpenImageIO reads)")->required();
    command->add_option("actual", options->actual, "The image to check")->required();
    command->add_option("--thresholds", options->thresholdsFile,
                        "A JSON file: max_difference, pixel_threshold, max_failing_share (%), max_mean, min_ssim");
    // Ranges checked by CLI11 (exit 2): a negative limit or an SSIM floor above 1 would fail every pair,
    // and no difference of 8-bit values exceeds 255 steps.
    command->add_option("--max-difference", options->maxDelta, "Largest channel difference allowed, 1/255 steps (2)")
        ->check(CLI::Range(0, 255));
    command->add_option("--pixel-threshold", options->pixelThreshold,
                        "A pixel fails when a channel differs by more than this, 1/255 steps (1)")
        ->check(CLI::Range(0, 255));
    command->add_option("--max-failing-share", options->maxFailingShare, "Share of failing pixels allowed, % (0.1)")
        ->check(CLI::Range(0.0, 100.0));
    command->add_option("--max-mean", options->maxMean, "Mean difference allowed, 1/255 steps (0.05)")
        ->check(CLI::Range(0.0, 255.0));
    command->add_option("--min-ssim", options->minSsim, "Smallest mean SSIM allowed (0.99)")->check(CLI::Range(0.0, 1.0));
    command->add_option("--diff", options->diff, "Write a heat map of the difference here");
    command->add_option("--side-by-side", options->sideBySide, "Write expected | actual | heat map here");
    return {command, [options] { return runCompare(*options); }};
}

}  // namespace tstyles::cli
