// A case of `tstyles check` rendered and compared with its golden, on the calling thread's context.
#include "check_case.h"

#include <chrono>

#include "../batch_frame_options.h"
#include "commands.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/gl/gl_loader.h"
#include "tstyles/image/image_io.h"
#include "tstyles/render/annotated_rendering.h"

namespace tstyles::cli {
namespace {

namespace fs = std::filesystem;

// The outcome of a case that is not updated, and what is wrong with it.
void judge(CaseResult& result, const CheckCase& entry, const ComparisonThresholds& thresholds,
           const std::optional<Image>& expected, const Image& actual) {
    if (!expected) {
        result.outcome = CaseOutcome::MissingGolden;
        result.problems.push_back("no golden image at " + entry.golden.string() + "; --update " + entry.name +
                                  " writes it (look at it first)");
    } else if (!result.difference) {
        result.outcome = CaseOutcome::Failed;
        result.problems.push_back("the golden is " + std::to_string(expected->width) + "x" +
                                  std::to_string(expected->height) + ", the render " + std::to_string(actual.width) +
                                  "x" + std::to_string(actual.height));
    } else {
        result.problems = thresholdsExceeded(*result.difference, thresholds);
        result.outcome = result.problems.empty() ? CaseOutcome::Passed : CaseOutcome::Failed;
    }
}

}  // namespace

CaseWorker::CaseWorker(GlBackend backend, const ShaderLibrary& shaders, CheckDatasets& datasets)
    : context_(createHeadlessContext(backend, glDebugOutputRequested())),
      glRenderer_(currentGlRenderer()),
      renderer_(shaders),
      datasets_(datasets) {}

const SceneOnSeries& CaseWorker::fit(const Scene& scene) {
    const Series& dataset = datasets_.series(scene.dataset);
    const bool sameSeries = fitted_ && uploaded_ == scene.dataset && fitted_->scene.display == scene.display;
    Series copy = dataset;
    fitted_.emplace(fitSceneToSeries(scene, std::move(copy)));
    if (!sameSeries) renderer_.setSeries(fitted_->series);
    uploaded_ = scene.dataset;
    return *fitted_;
}

CaseResult CaseWorker::check(const CheckCase& entry, Scene scene, bool update) {
    const auto start = std::chrono::steady_clock::now();
    CaseResult result{entry.name, entry.scene};
    if (entry.width) scene.width = *entry.width;
    if (entry.height) scene.height = *entry.height;
    const SceneOnSeries& fitted = fit(scene);
    AnnotatedRendering rendering(renderer_, fitted);
    // A case's pixels must not depend on the cases before it on this worker.
    Image actual = rendering.render(fitted.scene, asOneFrameRenderDrawsIt());
    const bool haveGolden = userPathKind({{}, "golden"}, entry.golden) == PathKind::RegularFile;
    std::optional<Image> expected;
    if (haveGolden) expected = readImage(entry.golden);
    const ChosenThresholds chosen = thresholdsOn(entry, glRenderer_);
    if (expected && expected->width == actual.width && expected->height == actual.height)
        result.difference = compareImages(actual, *expected, chosen.thresholds.pixelThreshold);
    if (update) {
        result.outcome = CaseOutcome::Updated;
        result.problems.push_back(!haveGolden ? "new golden " + entry.golden.string()
                                  : result.difference ? "golden rewritten; it changed by " + describe(*result.difference)
                                                      : "golden rewritten at a new size");
        result.actual = std::move(actual);
    } else {
        judge(result, entry, chosen.thresholds, expected, actual);
        if (result.outcome != CaseOutcome::Passed) {
            result.expected = std::move(expected);
            result.actual = std::move(actual);
        }
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace tstyles::cli
