// Distributed (sort-last) rendering against one process, run under `mpirun -np N`: every temporal
// compositor on the partial-overlap super-ellipsoid and on the hurricane (aligned, uneven z, missing
// values), lit-sphere styled scenes, whose gradients read ghost nodes at the block faces, and the
// sonar, whose pings are cut to the blocks, and the warped box, whose structured grid every
// process keeps whole.
// Process 0 also renders each case alone and compares; exit 0 when every case is within the
// thresholds below, 1 otherwise (the table says which). Each case is rendered twice distributed:
// with each process's block cut from the whole series, and with each process reading only its
// block (readManifestBlock); those two must be the same image to the bit.
// Then the automatic scene of each bundled dataset, read in blocks by every process, with its
// value-dependent parts (the STF opacity from the histogram, the gradient TSTF's "auto" range, the
// visible bounds the camera frames) fitted over the blocks: they must be the whole series' to the
// bit (the range within 1e-12, as the lattice's interpolation runs on cut grids), and the image
// within the thresholds below.
//   distributed_equivalence SOURCE_DIR OUTPUT_DIR
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/core/errors.h"
#include "tstyles/data/manifest.h"
#include "tstyles/distributed/block_reading.h"
#include "tstyles/distributed/distributed_rendering.h"
#include "tstyles/gl/headless_context.h"
#include "tstyles/image/image_comparison.h"
#include "tstyles/image/image_io.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/scene/temporal_compositors.h"

namespace {

using namespace tstyles;

// What a block split may change, in 1/255 steps of the stored values. The blocks take the samples
// of one whole render between them (a segment belongs to the block its middle lies in, on one
// lattice along the ray; only a jump over empty bricks that lands elsewhere in a block, whose bricks
// start at its first kept node, moves the one sample after it), so two things remain:
// - A ray that reaches the termination opacity (0.99) in a front block still gets up to the last
//   1 % from the blocks behind it, where one process shows the background: up to 2.5 steps.
//   With termination 1.0 every pixel of the hurricane at N = 4 is within 1/255 but one (below).
// - Near-ties: the hurricane's index-coloured MIP and time of maximum pick the time-step of the
//   largest density; where two time-steps nearly tie, the float rounding of a block's own voxel
//   mapping can flip the pick, and the pixel takes the other time-step's colour (one pixel of
//   65 536, 14/255 at N = 2 and 4).
// Measured on llvmpipe at 256x256, N = 2 and 4: at most 3/255 elsewhere, at most 0.005 % of the
// pixels beyond 2/255, mean at most 0.022/255 on the paper's scenes (docs/scaling.md), and 0.031/255
// on the hurricane's automatic scene since it is seen from above (6 December 2026: more rays reach
// the termination opacity in the upper block, which the lower one then tops up).
ComparisonThresholds distributedThresholds() {
    ComparisonThresholds thresholds;
    thresholds.maxDelta = 28;                 // a near-tie's other colour: 14 measured, twice that
    thresholds.pixelThreshold = 3;            // early termination
    thresholds.maxFailingFraction = 0.0002;   // 13 pixels of 65 536
    thresholds.maxMeanDelta = 0.04;  // 0.031 measured (the automatic hurricane from above)
    thresholds.minSsim = 0.999;
    return thresholds;
}

struct SceneCases {
    std::string sceneFile;  // under data/scenes
    std::vector<TemporalCompositor> compositors;
};

GlBackend backendFromEnvironment() {
    const char* name = std::getenv("TSTYLES_TEST_BACKEND");
    return glBackendFromString(name ? name : "auto").value_or(GlBackend::Auto);
}

// Prints one case's line on process 0 and keeps its images where it is beyond the thresholds;
// returns 1 for a failure, else 0.
int reportComparison(const MpiSession& mpi, const std::string& name, const Image& image, const Image& expected,
                     const std::filesystem::path& outputDir) {
    const ComparisonThresholds thresholds = distributedThresholds();
    const ImageDifference difference = compareImages(image, expected, thresholds.pixelThreshold);
    const bool passed = within(difference, thresholds);
    char line[200];
    std::snprintf(line, sizeof line, "%-52s %4d  %10.4f %%  %8.5f  %s\n", name.c_str(), difference.maxDelta,
                  100.0 * difference.failingFraction, difference.meanDelta, passed ? "ok" : "BEYOND");
    std::cout << line;
    if (passed) return 0;
    std::string stem = std::to_string(mpi.processCount()) + "-" + name;
    std::replace(stem.begin(), stem.end(), ' ', '-');
    std::filesystem::create_directories(outputDir);
    writeImage(image, outputDir / (stem + ".distributed.png"));
    writeImage(expected, outputDir / (stem + ".one-process.png"));
    return 1;
}

// The automatic scene of `dataset` with `compositor`, as `tstyles render DATASET --tc ...` makes
// it: fitted to the whole series by one process, and over the blocks each process read.
Scene automaticSceneFor(const Series& seriesOrOutline, const std::filesystem::path& dataset,
                        TemporalCompositor compositor, const OpacityWindow& window) {
    Scene scene = automaticScene(seriesOrOutline, dataset, window).scene;
    scene.compositor = compositor;
    applyAutomaticGradientColours(scene);
    scene.width = 256;
    scene.height = 256;
    return scene;
}

// Returns 1 where the scene fitted over the blocks or its image differs from one process's, else 0.
int compareAutomaticScene(const MpiSession& mpi, const std::filesystem::path& dataset, TemporalCompositor compositor,
                          const std::filesystem::path& outputDir) {
    const Series outline = loadSeriesOutline(dataset);
    const SceneOnSeries fittedOutline =
        fitSceneToSeries(automaticSceneFor(outline, dataset, compositor, OpacityWindow{}), outline);
    const Series displayOutline = fittedOutline.series;
    const DisplayFrame frame = fittedOutline.frame;
    Renderer renderer(ShaderLibrary::embedded());
    DistributedRendering distributed(
        mpi, renderer, fittedOutline,
        [&](const Bounds& box) { return readManifestBlock(dataset, {}, displayOutline, frame, box); },
        [&](const Series& block, const WholeSeries& wholeSeries) { renderer.setSeries(block, wholeSeries); }, true);
    const Image image = distributed.render(distributed.scene());
    if (!mpi.isFirst()) return 0;

    Series series = loadSeries(dataset);
    const OpacityWindow window = automaticOpacityWindow(series);
    const SceneOnSeries whole = fitSceneToSeries(automaticSceneFor(series, dataset, compositor, window), series);
    const std::string name = dataset.parent_path().filename().string() + " automatic " + toString(compositor);
    const Scene& fitted = distributed.scene();
    std::vector<std::string> differences;
    if (!(fitted.stf.curve.opacity == whole.scene.stf.curve.opacity)) differences.push_back("the STF opacity");
    const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); };
    if (!near(fitted.gradientTstf.rangeLow, whole.scene.gradientTstf.rangeLow) ||
        !near(fitted.gradientTstf.rangeHigh, whole.scene.gradientTstf.rangeHigh))
        differences.push_back("the gradient TSTF range (" + std::to_string(fitted.gradientTstf.rangeLow) + ".." +
                              std::to_string(fitted.gradientTstf.rangeHigh) + " against " +
                              std::to_string(whole.scene.gradientTstf.rangeLow) + ".." +
                              std::to_string(whole.scene.gradientTstf.rangeHigh) + ")");
    if (distributed.framed().lower != whole.framed.lower || distributed.framed().upper != whole.framed.upper)
        differences.push_back("the framed bounds");
    for (const std::string& difference : differences)
        std::cout << name << ": " << difference << " fitted over the blocks differs from one process's\n";
    const glm::dvec3 framedSize = distributed.framed().size();
    std::cout << name << ": " << fitted.stf.curve.opacity.size() << " opacity nodes, peak at "
              << fitted.stf.curve.opacity[1].at << "; gradient range " << fitted.gradientTstf.rangeLow << ".."
              << fitted.gradientTstf.rangeHigh << "; framed " << framedSize.x << " x " << framedSize.y << " x "
              << framedSize.z << " of " << whole.series.worldBounds().size().x << " x "
              << whole.series.worldBounds().size().y << " x " << whole.series.worldBounds().size().z << "\n";

    Renderer wholeRenderer(ShaderLibrary::embedded());
    wholeRenderer.setSeries(whole.series);
    const Image expected = AnnotatedRendering(wholeRenderer, whole).render(whole.scene);
    return reportComparison(mpi, name, image, expected, outputDir) + (differences.empty() ? 0 : 1);
}

int run(const std::filesystem::path& sourceDir, const std::filesystem::path& outputDir) {
    const MpiSession mpi;
    const std::vector<SceneCases> cases = {
        {"figure4-temporal-mip.json", builtInCompositors()},   // partial overlap
        {"figure5-focus-step5.json", builtInCompositors()},    // the hurricane
        {"figure4-styled-temporal-average.json",
         {compositorNamed("temporal-average"), compositorNamed("temporal-mip")}},
        {"figure1-styled-focus-step3.json", {compositorNamed("temporal-mip")}},
        // The sonar: each ping cut to the beams and range bins of the block.
        {"figure6-centre-index-tstf.json", {compositorNamed("temporal-mip"), compositorNamed("temporal-average")}},
        {"figure6-right-max-density-change.json", {compositorNamed("temporal-max-change")}},
        // A curvilinear (structured) grid, also kept whole, with lit-sphere styles.
        {"warped-box-styled.json", {compositorNamed("temporal-mip")}},
    };
    const auto context = createHeadlessContext(backendFromEnvironment(), false);
    int failures = 0;
    if (mpi.isFirst())
        std::cout << mpi.processCount() << " processes, " << context->description() << "\n"
                  << "case                                                  max  beyond 3/255  mean/255\n";
    for (const SceneCases& sceneCases : cases) {
        const std::filesystem::path sceneFile = sourceDir / "data" / "scenes" / sceneCases.sceneFile;
        Scene base = loadScene(sceneFile);
        base.width = 256;
        base.height = 256;
        SceneOnSeries fitted = fitSceneToSeries(base, loadSeries(base.dataset));
        // Every compositor's scene, with its automatic parts fitted to the whole series.
        std::vector<Scene> scenes;
        for (TemporalCompositor compositor : sceneCases.compositors) {
            Scene scene = fitted.scene;
            scene.compositor = compositor;
            scenes.push_back(fitAutomaticParts(scene, fitted.series));
        }
        std::optional<SceneOnSeries> whole;
        if (mpi.isFirst()) whole = fitted;
        // The same blocks read by each process itself, time-step by time-step, from the outline
        // fitted alike (readManifestBlock): no process holds the whole series.
        SceneOnSeries fittedOutline = fitSceneToSeries(base, loadSeriesOutline(base.dataset));
        const Series displayOutline = fittedOutline.series;  // grids without values
        const DisplayFrame frame = fittedOutline.frame;
        Renderer readRenderer(ShaderLibrary::embedded());
        DistributedRendering fromReadBlocks(
            mpi, readRenderer, std::move(fittedOutline),
            [&](const Bounds& box) { return readManifestBlock(base.dataset, {}, displayOutline, frame, box); },
            [&](const Series& block, const WholeSeries& wholeSeries) { readRenderer.setSeries(block, wholeSeries); });
        Renderer blockRenderer(ShaderLibrary::embedded());
        DistributedRendering distributed(mpi, blockRenderer, std::move(fitted),
                                         [&](const Series& block, const WholeSeries& wholeSeries) {
                                             blockRenderer.setSeries(block, wholeSeries);
                                         });
        std::optional<Renderer> wholeRenderer;
        if (mpi.isFirst()) {
            wholeRenderer.emplace(ShaderLibrary::embedded());
            wholeRenderer->setSeries(whole->series);
        }
        for (const Scene& scene : scenes) {
            const Image image = distributed.render(scene);
            const Image fromRead = fromReadBlocks.render(scene);
            if (!mpi.isFirst()) continue;
            // Read blocks are the cut blocks exactly, so the two distributed images are the same.
            const ImageDifference readDifference = compareImages(fromRead, image, 0);
            if (readDifference.maxDelta != 0) {
                ++failures;
                std::cout << sceneCases.sceneFile << " " << toString(scene.compositor)
                          << ": the blocks each process read differ from the blocks cut from the whole series: "
                          << describe(readDifference) << "\n";
            }
            const Image expected = AnnotatedRendering(*wholeRenderer, *whole).render(scene);
            failures += reportComparison(mpi, sceneCases.sceneFile + " " + toString(scene.compositor), image, expected,
                                         outputDir);
        }
    }
    // The max density change fits the gradient range to another compositor's; the sonar, the
    // slowest to render, takes the MIP alone.
    for (const char* dataset : {"superellipsoid", "hurricane", "sonar", "warped-box"})
        for (TemporalCompositor compositor :
             {compositorNamed("temporal-mip"), compositorNamed("temporal-max-change")})
            if (std::string(dataset) != "sonar" || compositor == compositorNamed("temporal-mip"))
                failures += compareAutomaticScene(mpi, sourceDir / "data" / dataset / "series.json", compositor,
                                                  outputDir);
    if (mpi.isFirst()) std::cout << (failures == 0 ? "all within the thresholds\n" : "some cases are beyond the thresholds\n");
    return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: distributed_equivalence SOURCE_DIR OUTPUT_DIR\n";
        return 2;
    }
    try {
        return run(argv[1], argv[2]);
    } catch (const tstyles::FailedOnAnotherProcess&) {
        return 0;  // process 0 reports and fails the test (as in tstyles' main.cpp)
    } catch (const std::exception& error) {
        std::cerr << "distributed_equivalence: " << error.what() << "\n";
        return 1;
    }
}
