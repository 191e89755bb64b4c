// `tstyles bench`: renders a fixed matrix of scenes (dataset x temporal compositor x image size)
// headless and reports per-frame medians, ray and sample counts and texture memory.
#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>
#include <sys/resource.h>

#include <CLI/CLI.hpp>

#include "bench_datasets.h"
#include "bench_distributed.h"
#include "bench_scaling.h"
#include "commands.h"
#include "image_size_text.h"
#include "gpu_memory_option.h"
#include "scene_source.h"
#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/data/manifest.h"
#include "tstyles/gl/gl_api.h"
#include "tstyles/render/renderer.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/data/format_listing.h"

namespace tstyles::cli {
namespace {

std::vector<std::string> defaultDatasets() {
    std::vector<std::string> folders;
    for (const auto& dataset : benchDatasets()) folders.push_back(dataset.folder);
    return folders;
}

struct BenchOptions {
    // Datasets of the user's (any format `render` reads): their automatic scenes are timed instead of
    // the bundled matrix.
    std::vector<std::filesystem::path> files;
    DatasetOptions dataset;  // how they are read (--var, --steps, ...)
    std::vector<std::string> sizeTexts{"512", "1024"};
    std::vector<glm::ivec2> sizes;  // from sizeTexts
    int frames = 7;
    int warmup = 2;
    std::optional<std::filesystem::path> json;
    std::vector<std::string> datasets = defaultDatasets();
    bool baseline = false;
    // The scaling run instead of the matrix: super-ellipsoid series of these lengths.
    std::vector<int> scalingSteps;
    bool styled = false;
    bool automatic = false;  // --automatic: the bundled datasets' automatic scenes too
    std::vector<std::string> rayModes{"composite"};  // --ray: each compositor with each mode
    bool distributed = false;  // sort-last over the MPI processes (bench_distributed.h)
    bool stages = false;       // also time the passes and the raycasting pass' parts (PassClock)
    GpuMemoryOption gpuMemory;
    GlOptions gl;
};

// A user's scene: a file's automatic scene, or a scene file as written, fitted to its series, and
// what its camera frames.
struct AutomaticBenchScene {
    Scene scene;
    Bounds framed;
};

struct BenchCase {
    std::string dataset;
    // The bundled scene that supplies camera and transfer functions, "automatic", or "scene file"
    std::string scene;
    TemporalCompositor compositor;
    RayMode rayMode;
    glm::ivec2 size;
    std::optional<AutomaticBenchScene> automatic;  // a user's scene, used as it is
};

// The compositor, and the ray mode where it is not the default: "temporal-mip", "temporal-mip+maximum".
std::string methodName(const BenchCase& benchCase) {
    std::string name = toString(benchCase.compositor);
    if (benchCase.rayMode != kCompositeRay) name += "+" + toString(benchCase.rayMode);
    return name;
}

// Where a case's device time goes (--stages): medians of the pass clocks (render/pass_clock.h) over
// the timed frames.
struct StageTimes {
    double entryExitMs = 0.0;
    double raycastMs = 0.0;   // the whole raycasting pass
    double raySetupMs = 0.0;  // the pass with RaycastPart::RaySetup: no sample taken
    double marchMs = 0.0;     // the pass with RaycastPart::March: rays run to their exit
    std::uint64_t marchSamples = 0;
    // The march scaled to the samples the whole pass takes (its rays end early), and what is left
    // of the whole pass after setup and march: fetching, compositing and styling.
    double marchAtFrameSamplesMs(std::uint64_t frameSamples) const {
        if (marchSamples == 0) return marchMs - raySetupMs;
        return (marchMs - raySetupMs) * double(frameSamples) / double(marchSamples);
    }
    double samplingMs(std::uint64_t frameSamples) const {
        return raycastMs - raySetupMs - marchAtFrameSamplesMs(frameSamples);
    }
};

struct BenchResult {
    BenchCase benchCase;
    std::size_t timeSteps = 0;
    double medianMs = 0.0;
    double maxMs = 0.0;
    // CPU time of the whole process (llvmpipe's threads included) per frame: on a shared machine
    // it moves far less with other work than the wall clock does.
    double medianCpuMs = 0.0;
    std::optional<double> naiveMedianMs;  // with --baseline
    RaycastStatistics statistics;
    std::size_t seriesTextureBytes = 0;
    std::size_t frameTextureBytes = 0;
    // What --max-gpu-memory (or the driver's memory) changed in the series' storage; empty: as read.
    std::vector<std::string> gpuStorageChanges;
    std::optional<StageTimes> stages;  // with --stages
};

// User and system time of every thread of this process so far.
double processCpuMilliseconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto ms = [](const timeval& time) { return 1e3 * double(time.tv_sec) + 1e-3 * double(time.tv_usec); };
    return ms(usage.ru_utime) + ms(usage.ru_stime);
}

struct FrameTimes {
    std::vector<double> wallMs;
    std::vector<double> cpuMs;
    std::vector<double> entryExitGpuMs;  // with FrameOptions::timePasses
    std::vector<double> raycastGpuMs;
};

BenchResult runCase(Renderer& renderer, const Series& series, const BenchCase& benchCase,
                    const BenchOptions& options) {
    Scene scene = benchCase.automatic
                      ? benchCase.automatic->scene
                      : loadScene(bundledDataDirectory() / "scenes" / (benchCase.scene + ".json"));
    scene.compositor = benchCase.compositor;
    scene.rayMode = benchCase.rayMode;
    scene.width = benchCase.size.x;
    scene.height = benchCase.size.y;
    const Bounds framed = benchCase.automatic ? benchCase.automatic->framed : series.worldBounds();
    FrameOptions frame;
    frame.size = benchCase.size;
    // Every frame turns the camera a little, as a user orbiting would, so no frame repeats.
    auto viewForFrame = [&](int index) {
        Camera camera = scene.camera;
        if (auto* orbit = std::get_if<OrbitCamera>(&camera.pose)) orbit->azimuthDeg += 2.0 * index;
        return resolveView(camera, framed, series.worldBounds(), benchCase.size.x, benchCase.size.y);
    };
    auto timeFrames = [&](const FrameOptions& timed) {
        for (int i = 0; i < options.warmup; ++i) renderer.draw(scene, viewForFrame(i), timed);
        glFinish();
        FrameTimes times;
        for (int i = 0; i < options.frames; ++i) {
            const View view = viewForFrame(i);
            const double cpuStart = processCpuMilliseconds();
            const auto start = std::chrono::steady_clock::now();
            renderer.draw(scene, view, timed);
            glFinish();
            times.wallMs.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            times.cpuMs.push_back(processCpuMilliseconds() - cpuStart);
            if (timed.timePasses) {
                const FramePassTimes passes = renderer.lastPassTimes();
                times.entryExitGpuMs.push_back(passes.entryExitMs);
                times.raycastGpuMs.push_back(passes.raycastMs);
            }
        }
        return times;
    };
    frame.timePasses = options.stages;
    const FrameTimes times = timeFrames(frame);
    BenchResult result{benchCase, series.size(), median(times.wallMs),
                       *std::max_element(times.wallMs.begin(), times.wallMs.end()), median(times.cpuMs),
                       std::nullopt, {}, 0, 0, {}, std::nullopt};
    if (options.stages) {
        StageTimes stages;
        stages.entryExitMs = median(times.entryExitGpuMs);
        stages.raycastMs = median(times.raycastGpuMs);
        FrameOptions part = frame;
        part.raycastPart = RaycastPart::RaySetup;
        stages.raySetupMs = median(timeFrames(part).raycastGpuMs);
        part.raycastPart = RaycastPart::March;
        stages.marchMs = median(timeFrames(part).raycastGpuMs);
        part.timePasses = false;
        part.collectStatistics = true;
        renderer.draw(scene, viewForFrame(0), part);
        stages.marchSamples = renderer.lastStatistics().samples;
        result.stages = stages;
    }
    if (options.baseline) {
        FrameOptions naive = frame;
        naive.naive = true;
        result.naiveMedianMs = median(timeFrames(naive).wallMs);
    }
    frame.timePasses = false;
    frame.collectStatistics = true;  // counted in an extra, untimed frame: atomics cost time
    renderer.draw(scene, viewForFrame(0), frame);
    result.statistics = renderer.lastStatistics();
    result.seriesTextureBytes = renderer.seriesTextureBytes();
    result.frameTextureBytes = renderer.frameTextureBytes();
    return result;
}

// The width of the table's compositor column: its longest entry and two spaces.
int methodColumnWidth(const std::vector<BenchResult>& results) {
    std::size_t width = std::string("compositor").size();
    for (const BenchResult& result : results) width = std::max(width, methodName(result.benchCase).size());
    return int(width) + 2;
}

std::string mebibytes(std::size_t bytes) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << double(bytes) / (1024.0 * 1024.0);
    return text.str();
}

void printTable(const std::vector<BenchResult>& results, const std::string& device) {
    std::cout << "device: " << device << "\n";
    const bool styled = results.front().benchCase.scene.find("styled") != std::string::npos;
    if (results.front().benchCase.automatic)
        std::cout << "scenes: each dataset's automatic scene, as `tstyles render FILE` draws it, and each scene file "
                     "as written\n";
    else
        std::cout << "scenes: data/scenes/<dataset's prefix>" << (styled ? "styled-" : "") << "*.json\n";
    const int method = methodColumnWidth(results);
    std::cout << std::left << std::setw(28) << "dataset" << std::setw(method) << "compositor" << std::right
              << std::setw(6) << "n" << std::setw(11) << "size" << std::setw(11) << "median ms" << std::setw(9)
              << "max ms" << std::setw(9) << "cpu ms" << std::setw(10) << "rays" << std::setw(13) << "samples" << std::setw(13)
              << "fetches" << std::setw(11) << "tex MiB";
    if (results.front().naiveMedianMs) std::cout << std::setw(11) << "naive ms" << std::setw(10) << "speed-up";
    std::cout << "\n";
    for (const auto& r : results) {
        std::cout << std::left << std::setw(28) << r.benchCase.dataset << std::setw(method)
                  << methodName(r.benchCase) << std::right << std::setw(6) << r.timeSteps << std::setw(11)
                  << widthByHeightText(r.benchCase.size) << std::setw(11) << std::fixed << std::setprecision(1) << r.medianMs
                  << std::setw(9) << r.maxMs << std::setw(9) << r.medianCpuMs << std::setw(10) << r.statistics.rays << std::setw(13)
                  << r.statistics.samples << std::setw(13) << r.statistics.fetches << std::setw(11)
                  << mebibytes(r.seriesTextureBytes + r.frameTextureBytes);
        if (r.naiveMedianMs)
            std::cout << std::setw(11) << std::setprecision(1) << *r.naiveMedianMs << std::setw(9)
                      << std::setprecision(1) << *r.naiveMedianMs / r.medianMs << "x";
        std::cout << "\n";
    }
}

// --stages: the GPU's milliseconds per pass and part (docs/performance.md, "Where a frame's GPU time goes").
void printStages(const std::vector<BenchResult>& results) {
    std::cout << "\nms per pass and part (medians; timer queries on a GPU, glFinish and the wall clock on a CPU "
                 "rasterizer):\n";
    const int method = methodColumnWidth(results);
    std::cout << std::left << std::setw(28) << "dataset" << std::setw(method) << "compositor" << std::right << std::setw(11)
              << "size" << std::setw(12) << "entry/exit" << std::setw(11) << "raycast" << std::setw(11) << "ray setup"
              << std::setw(9) << "march" << std::setw(11) << "sampling" << std::setw(12) << "march alone"
              << std::setw(15) << "march samples" << "\n";
    for (const auto& r : results) {
        const StageTimes& stages = *r.stages;
        std::cout << std::left << std::setw(28) << r.benchCase.dataset << std::setw(method)
                  << methodName(r.benchCase) << std::right << std::setw(11)
                  << widthByHeightText(r.benchCase.size)
                  << std::fixed << std::setprecision(1) << std::setw(12) << stages.entryExitMs << std::setw(11)
                  << stages.raycastMs << std::setw(11) << stages.raySetupMs << std::setw(9)
                  << stages.marchAtFrameSamplesMs(r.statistics.samples) << std::setw(11)
                  << stages.samplingMs(r.statistics.samples) << std::setw(12) << stages.marchMs << std::setw(15)
                  << stages.marchSamples << "\n";
    }
    std::cout << "march: the march's time per sample (march alone, whose rays run to their exit, less the ray setup)\n"
                 "times the frame's samples; sampling: the rest of the raycasting pass (fetches, compositor, styles)\n";
}

nlohmann::json toJson(const std::vector<BenchResult>& results, const std::string& device) {
    nlohmann::json cases = nlohmann::json::array();
    for (const auto& r : results)
        cases.push_back({{"dataset", r.benchCase.dataset}, {"scene", r.benchCase.scene},
                         {"compositor", toString(r.benchCase.compositor)},
                         {"ray", toString(r.benchCase.rayMode)}, {"time_steps", r.timeSteps},
                         {"width", r.benchCase.size.x}, {"height", r.benchCase.size.y},
                         {"median_ms", r.medianMs}, {"max_ms", r.maxMs}, {"median_cpu_ms", r.medianCpuMs}, {"rays", r.statistics.rays},
                         {"samples", r.statistics.samples}, {"fetches", r.statistics.fetches},
                         {"series_texture_bytes", r.seriesTextureBytes},
                         {"frame_texture_bytes", r.frameTextureBytes},
                         {"gpu_storage_changes", r.gpuStorageChanges},
                         {"naive_median_ms", r.naiveMedianMs ? nlohmann::json(*r.naiveMedianMs) : nlohmann::json()},
                         {"speed_up", r.naiveMedianMs ? nlohmann::json(*r.naiveMedianMs / r.medianMs) : nlohmann::json()}});
    for (std::size_t i = 0; i < results.size(); ++i) {
        if (!results[i].stages) continue;
        const StageTimes& stages = *results[i].stages;
        const std::uint64_t samples = results[i].statistics.samples;
        cases[i]["stages_gpu_ms"] = {{"entry_exit", stages.entryExitMs}, {"raycast", stages.raycastMs},
                                     {"ray_setup", stages.raySetupMs},
                                     {"march", stages.marchAtFrameSamplesMs(samples)},
                                     {"sampling", stages.samplingMs(samples)}, {"march_alone", stages.marchMs},
                                     {"march_alone_samples", stages.marchSamples}};
    }
    return {{"device", device}, {"cases", cases}};
}

// Whether the compositor goes with the ray mode (rayModeProblem); a pair that does not is left
// out of the matrix with a note.
bool goTogether(TemporalCompositor compositor, RayMode mode) {
    Scene scene;
    scene.compositor = compositor;
    scene.rayMode = mode;
    const auto problem = rayModeProblem(scene);
    if (problem) std::cerr << "note: skipping " << toString(compositor) << " with ray " << toString(mode) << ": " << problem->problem << "\n";
    return !problem;
}

// Every compositor with every ray mode at every size on one series.
void runSeries(Renderer& renderer, const Series& series, const BenchDataset& dataset, const BenchOptions& options,
               std::vector<BenchResult>& results) {
    const std::vector<std::string> storageChanges =
        residencyChanges(series, uploadWithinGpuMemory(renderer, series, options.gpuMemory, DatasetOptions{}));
    for (auto compositor : kBenchCompositors)
        for (const std::string& modeName : options.rayModes) {
            const RayMode mode = *rayModeFromString(modeName);
            if (!goTogether(compositor, mode)) continue;
            for (glm::ivec2 size : options.sizes) {
                results.push_back(runCase(renderer, series,
                                          {dataset.folder, benchSceneFor(dataset, compositor, options.styled),
                                           compositor, mode, size},
                                          options));
                results.back().gpuStorageChanges = storageChanges;
                std::cerr << "." << std::flush;
            }
        }
}

void runMatrix(Renderer& renderer, const BenchOptions& options, std::vector<BenchResult>& results) {
    for (const auto& folder : options.datasets) {
        const std::filesystem::path manifest = bundledDataDirectory() / folder / "series.json";
        if (userPathKind({"", "--datasets"}, manifest) == PathKind::Missing) {
            std::cerr << "note: skipping dataset " << folder << ": " << manifest.string() << " does not exist\n";
            continue;
        }
        runSeries(renderer, loadSeries(manifest), benchDatasetFor(folder), options, results);
    }
}

// Each dataset's automatic scene (docs/automatic-scene.md), as `render FILE` draws it, and each scene
// file as written, at every size; --ray replaces its ray mode where given.
void runAutomaticScenes(Renderer& renderer, const std::vector<std::pair<std::string, std::filesystem::path>>& files,
                        const BenchOptions& options, bool raysGiven, std::vector<BenchResult>& results) {
    for (const auto& [name, file] : files) {
        SceneAndSeries opened = openSceneOrDataset({file}, {}, options.dataset);
        const std::string sceneKind = opened.explanation.empty() ? "scene file" : "automatic";
        SceneOnSeries fitted = fitSceneToSeries(std::move(opened.scene), std::move(opened.series));
        const std::vector<std::string> storageChanges = residencyChanges(
            fitted.series, uploadWithinGpuMemory(renderer, fitted.series, options.gpuMemory, options.dataset));
        const std::vector<RayMode> modes = [&] {
            if (!raysGiven) return std::vector<RayMode>{fitted.scene.rayMode};
            std::vector<RayMode> given;
            for (const std::string& modeName : options.rayModes) given.push_back(*rayModeFromString(modeName));
            return given;
        }();
        for (const RayMode mode : modes) {
            if (!goTogether(fitted.scene.compositor, mode)) continue;
            for (glm::ivec2 size : options.sizes) {
                BenchCase benchCase{name, sceneKind, fitted.scene.compositor, mode, size,
                                    AutomaticBenchScene{fitted.scene, fitted.framed}};
                results.push_back(runCase(renderer, fitted.series, benchCase, options));
                results.back().gpuStorageChanges = storageChanges;
                std::cerr << "." << std::flush;
            }
        }
    }
}

// Partial and full overlap for each n; the series are generated on the fly (bench_scaling.h).
void runScaling(Renderer& renderer, const BenchOptions& options, std::vector<BenchResult>& results) {
    for (int steps : options.scalingSteps)
        for (bool aligned : {false, true}) {
            const BenchDataset dataset{scalingDatasetName(steps, aligned), "", "figure4-"};
            runSeries(renderer, buildScalingSeries(steps, aligned), dataset, options, results);
        }
}

int runBench(const BenchOptions& options, bool raysGiven) {
    if (!options.files.empty() &&
        (options.styled || !options.scalingSteps.empty() || options.distributed || options.automatic))
        throwInputError("", "FILE", "times the files' own scenes; it takes neither --styled, --scaling, "
                                    "--distributed nor --automatic");
    if (options.distributed) {
        if (options.baseline || options.styled || options.stages || !options.scalingSteps.empty() || options.automatic)
            throwInputError("", "--distributed",
                            "measures the flat matrix; it takes neither --baseline, --styled, --stages, --scaling nor "
                            "--automatic");
        if (options.rayModes != std::vector<std::string>{"composite"})
            throwInputError("", "--distributed",
                            "merges the processes' frames front to back, which holds for the composite ray mode only; "
                            "measure other ray modes without --distributed");
        return runDistributedBench(
            {options.datasets, options.sizes, options.frames, options.warmup, options.json, options.gpuMemory, options.gl});
    }
    const auto context = createHeadlessContext(parseBackend(options.gl.backend), false);
    Renderer renderer(ShaderLibrary::fromEnvironment(options.gl.shaderDirectory));
    std::vector<BenchResult> results;
    if (!options.files.empty()) {
        std::vector<std::pair<std::string, std::filesystem::path>> files;
        for (const auto& file : options.files) files.emplace_back(file.filename().string(), file);
        runAutomaticScenes(renderer, files, options, raysGiven, results);
    } else if (options.scalingSteps.empty()) {
        runMatrix(renderer, options, results);
        if (options.automatic) {
            // The bundled datasets as a user's files: their automatic scenes, named "<folder> (automatic)".
            std::vector<std::pair<std::string, std::filesystem::path>> files;
            for (const auto& folder : options.datasets)
                if (const auto manifest = bundledDataDirectory() / folder / "series.json";
                    userPathKind({"", "--datasets"}, manifest) != PathKind::Missing)
                    files.emplace_back(folder + " (automatic)", manifest);
            runAutomaticScenes(renderer, files, options, raysGiven, results);
        }
    } else {
        runScaling(renderer, options, results);
    }
    std::cerr << "\n";
    if (results.empty()) {
        std::cerr << "tstyles bench: none of the datasets is there (generate them with the build)\n";
        return kExitBadInput;
    }
    printTable(results, context->description());
    if (options.stages) printStages(results);
    if (options.json) writeFileAtomically(*options.json, toJson(results, context->description()).dump(2) + "\n");
    return kExitSuccess;
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* command = app.add_subcommand(
        "bench", "Benchmark the bundled scenes (every temporal compositor on each dataset), or the automatic scene of "
                 "your own files; medians of several frames");
    command->add_option("files", options->files,
                        std::string("Datasets whose automatic scenes to time, as `render FILE` draws them, or scene "
                                    "files to time as written, instead of the bundled matrix: ") + datasetKindsText());
    command->add_option("--sizes", options->sizeTexts,
                        "Image sizes to render: WIDTHxHEIGHT (e.g. 1920x1080), or one number for a square (default: 512 1024)");
    command->add_option("--frames", options->frames, "Timed frames per case (the median is reported)")
        ->check(CLI::Range(1, 1000));
    command->add_option("--warmup", options->warmup, "Untimed frames first (shader compilation, caches)")
        ->check(CLI::Range(0, 100));
    command->add_option("--datasets", options->datasets, "Bundled datasets (folders under data/)");
    command->add_option("--json", options->json, "Also write the results as JSON to this file");
    command->add_flag("--baseline", options->baseline,
                      "Also time the naive raycaster (every time-step at every sample, no skipping) in the same run "
                      "and print the speed-up");
    command->add_option("--scaling", options->scalingSteps,
                        "Scaling run instead of the matrix: the super-ellipsoid simulated for longer with these "
                        "numbers of time-steps, partial and full overlap (e.g. --scaling 10 20 40 80 160)")
        ->check(CLI::Range(2, 1000));
    command->add_flag("--styled", options->styled, "Measure the Figure 4 scenes with lit-sphere styles");
    command->add_flag("--automatic", options->automatic,
                      "Also time the bundled datasets' automatic scenes (what `render DATASET` draws), after the matrix");
    command->add_option("--ray", options->rayModes,
                        "Ray modes to measure each compositor with (docs/ray-modes.md; default: composite); pairs "
                        "that do not go together are left out with a note")
        ->check(CLI::IsMember(rayModeNames()));
    command->add_flag("--stages", options->stages,
                      "Also time each frame's passes (entry/exit, raycasting; timer queries on a GPU, glFinish and the "
                      "wall clock on llvmpipe) and the raycasting pass' parts (ray setup, march, sampling) and print "
                      "where the time goes");
    command->add_flag("--distributed", options->distributed,
                      "Under mpirun: render sort-last over the MPI processes and report each frame's rendering (the "
                      "slowest block) and compositing, for strong scaling (docs/scaling.md)");
    addGpuMemoryOption(*command, options->gpuMemory);
    addGlOptions(*command, options->gl);
    addDatasetOptions(*command, options->dataset);
    CLI::Option* ray = command->get_option("--ray");
    return {command, [options, ray] {
        parseGpuMemoryOption(options->gpuMemory);  // a bad size fails before anything is read
        options->sizes.clear();
        for (const std::string& text : options->sizeTexts)
            options->sizes.push_back(parseImageSizeOption(text, "--sizes", 16, 8192));
        return runBench(*options, ray->count() > 0);
    }};
}

}  // namespace tstyles::cli
