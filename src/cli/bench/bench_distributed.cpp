// Strong scaling of sort-last rendering (bench_distributed.h).
#include "bench_distributed.h"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "bench_datasets.h"
#include "image_size_text.h"
#include "tstyles/core/atomic_file.h"
#include "tstyles/core/bundled_data.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/data/manifest.h"
#include "tstyles/distributed/distributed_rendering.h"
#include "tstyles/scene/scene_file.h"

namespace tstyles::cli {
namespace {

struct DistributedResult {
    std::string dataset;
    TemporalCompositor compositor = compositorNamed("temporal-mip");
    glm::ivec2 size{0};
    double frameMs = 0.0;      // median of the whole frame on process 0 (render, composite, background)
    double renderMs = 0.0;     // median over frames of the slowest process's block
    double compositeMs = 0.0;  // median over frames of the slowest process's compositing
    double blockBytes = 0.0;   // the largest block's textures
};

// Every compositor at every size on one dataset, with one DistributedRendering.
void runDataset(const MpiSession& mpi, Renderer& renderer, const std::string& folder,
                const DistributedBenchOptions& options, std::vector<DistributedResult>& results) {
    const BenchDataset dataset = benchDatasetFor(folder);
    std::vector<Scene> scenes;
    std::optional<Series> series;
    mpi.together("reading " + folder, [&] {
        series = loadSeries(bundledDataDirectory() / folder / "series.json");
        for (TemporalCompositor compositor : kBenchCompositors) {
            Scene scene = loadScene(bundledDataDirectory() / "scenes" / (benchSceneFor(dataset, compositor, false) + ".json"));
            scene.compositor = compositor;
            scenes.push_back(std::move(scene));
        }
    });
    SceneOnSeries fitted = fitSceneToSeries(scenes.front(), std::move(*series));
    for (Scene& scene : scenes) scene = fitAutomaticParts(scene, fitted.series);
    DistributedRendering rendering(mpi, renderer, std::move(fitted),
                                   [&](const Series& block, const WholeSeries& whole) {
                                       uploadWithinGpuMemory(renderer, block, options.gpuMemory, DatasetOptions{}, whole);
                                   });
    const double blockBytes = mpi.maximum(double(renderer.seriesTextureBytes()));
    for (Scene scene : scenes)
        for (glm::ivec2 size : options.sizes) {
            scene.width = size.x;
            scene.height = size.y;
            std::vector<double> frame, render, composite;
            for (int index = -options.warmup; index < options.frames; ++index) {
                // Every frame turns the camera a little, as `bench` does, so no frame repeats.
                Scene turned = scene;
                if (auto* orbit = std::get_if<OrbitCamera>(&turned.camera.pose)) orbit->azimuthDeg += 2.0 * index;
                const auto start = std::chrono::steady_clock::now();
                rendering.render(turned);
                const double frameMs =
                    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
                const double renderMs = mpi.maximum(rendering.lastTimes().render);
                const double compositeMs = mpi.maximum(rendering.lastTimes().composite);
                if (index < 0) continue;
                frame.push_back(frameMs);
                render.push_back(renderMs);
                composite.push_back(compositeMs);
            }
            results.push_back({folder, scene.compositor, size, median(frame), median(render), median(composite), blockBytes});
            if (mpi.isFirst()) std::cerr << "." << std::flush;
        }
}

void printTable(const std::vector<DistributedResult>& results, int processes, const std::string& device) {
    std::cout << "device: " << device << "\n" << processes << " processes, sort-last (radix-k)\n";
    std::cout << std::left << std::setw(24) << "dataset" << std::setw(21) << "compositor" << std::right << std::setw(11)
              << "size" << std::setw(11) << "frame ms" << std::setw(11) << "render ms" << std::setw(14)
              << "composite ms" << std::setw(15) << "block tex MiB" << "\n";
    for (const auto& r : results)
        std::cout << std::left << std::setw(24) << r.dataset << std::setw(21) << toString(r.compositor) << std::right
                  << std::setw(11) << widthByHeightText(r.size) << std::fixed << std::setprecision(1) << std::setw(11) << r.frameMs
                  << std::setw(11) << r.renderMs << std::setw(14) << r.compositeMs << std::setw(15)
                  << r.blockBytes / (1024.0 * 1024.0) << "\n";
}

nlohmann::json toJson(const std::vector<DistributedResult>& results, int processes, const std::string& device) {
    nlohmann::json cases = nlohmann::json::array();
    for (const auto& r : results)
        cases.push_back({{"dataset", r.dataset}, {"compositor", toString(r.compositor)}, {"width", r.size.x}, {"height", r.size.y},
                         {"frame_median_ms", r.frameMs}, {"render_median_ms", r.renderMs},
                         {"composite_median_ms", r.compositeMs}, {"largest_block_texture_bytes", r.blockBytes}});
    return {{"device", device}, {"processes", processes}, {"cases", cases}};
}

}  // namespace

int runDistributedBench(const DistributedBenchOptions& options) {
    const MpiSession mpi;
    std::unique_ptr<HeadlessContext> context;
    std::optional<Renderer> renderer;
    mpi.together("starting OpenGL", [&] {
        context = createHeadlessContext(parseBackend(options.gl.backend), false);
        renderer.emplace(ShaderLibrary::fromEnvironment(options.gl.shaderDirectory));
    });
    std::vector<DistributedResult> results;
    for (const std::string& folder : options.datasets) {
        if (userPathKind({"", "--datasets"}, bundledDataDirectory() / folder / "series.json") == PathKind::Missing) {
            if (mpi.isFirst()) std::cerr << "note: skipping dataset " << folder << ": it is not under data/\n";
            continue;
        }
        runDataset(mpi, *renderer, folder, options, results);
    }
    if (!mpi.isFirst()) return kExitSuccess;
    std::cerr << "\n";
    if (results.empty()) {
        std::cerr << "tstyles bench: none of the datasets is there (generate them with the build)\n";
        return kExitBadInput;
    }
    printTable(results, mpi.processCount(), context->description());
    if (options.json)
        writeFileAtomically(*options.json, toJson(results, mpi.processCount(), context->description()).dump(2) + "\n");
    return kExitSuccess;
}

}  // namespace tstyles::cli
