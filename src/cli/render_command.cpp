// `tstyles render SCENE -o OUT`: one scene to one image file, headless.
#include <chrono>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "annotation_options.h"
#include "tstyles/render/annotated_rendering.h"
#include "animation_options.h"
#include "commands.h"
#include "distributed_source.h"
#include "gpu_memory_option.h"
#include "scene_source.h"
#include "tstyles/scene/automatic_scene.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/process_memory.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/distributed/distributed_rendering.h"
#include "tstyles/image/image_io.h"
#include "tstyles/render/renderer.h"
#include "tstyles/scene/scene_file.h"
#include "tstyles/data/format_listing.h"

namespace tstyles::cli {
namespace {

struct RenderOptions {
    std::vector<std::filesystem::path> inputs;  // a scene file, or the files of one dataset
    std::filesystem::path output;
    std::optional<int> width;
    std::optional<int> height;
    SceneOverrides overrides;
    std::vector<std::string> styleOverrides;  // NAME=FILE
    GlOptions gl;
    std::vector<std::filesystem::path> datasetFiles;  // --dataset: instead of the scene's dataset
    DatasetOptions dataset;
    GpuMemoryOption gpuMemory;
    std::optional<int> frame;      // --frame K: the scene of frame K of the animation
    AnimationOptions animation;    // the presets of `animate`, for --frame
    AnnotationOptions annotations;
    bool distributed = false;      // --distributed: sort-last over the MPI processes
};

// --style NAME=FILE: every colour node of the scene that uses style NAME reads FILE instead, so a
// look can be tried on a scene without editing it.
void overrideStyles(Scene& scene, const std::vector<std::string>& overrides) {
    for (const std::string& entry : overrides) {
        const auto equals = entry.find('=');
        if (equals == std::string::npos || equals == 0 || equals + 1 == entry.size())
            throwInputError("", "--style", "expected NAME=FILE, got \"" + entry + "\"");
        const std::string name = entry.substr(0, equals);
        const std::string file = userAbsolutePath({"", "--style"}, entry.substr(equals + 1)).string();
        bool used = false;
        for (TransferFunction1D* curve : {&scene.stf.curve, &scene.indexTstf.curve, &scene.gradientTstf.curve})
            for (ColorNode& node : curve->color)
                if (node.style == name) {
                    node.style = file;
                    used = true;
                }
        if (!used) throwInputError("", "--style", "the scene uses no style named \"" + name + "\"");
    }
}

// The scene and series the options ask for (`opened`), fitted to each other.
SceneOnSeries fittedScene(const RenderOptions& options, SceneAndSeries opened) {
    Scene& scene = opened.scene;
    if (options.width) scene.width = *options.width;
    if (options.height) scene.height = *options.height;
    applySceneOverrides(opened, options.overrides);
    overrideStyles(scene, options.styleOverrides);
    applyAnnotationOptions(scene, options.annotations);
    if (!options.frame && (hasPreset(options.animation) || options.animation.frames || options.animation.framesPerSecond))
        throwInputError("", "--frame", "missing: the animation options of render choose the animation that --frame K "
                                       "takes a frame of");
    return fitSceneToSeries(std::move(scene), std::move(opened.series));
}

// A fitted scene at the frame asked for (--frame K of its animation or the presets'), its exposure
// and difference steps checked against the series.
SceneOnSeries atRequestedFrame(const RenderOptions& options, SceneOnSeries fitted) {
    if (options.frame) {
        const Animation animation = animationFor(fitted.scene, fitted.series.size(), options.animation,
                                                  options.inputs.front().string(), cameraDistance(fitted));
        if (*options.frame >= animation.frames)
            throwInputError("", "--frame", std::to_string(*options.frame) + " is past the animation's last frame (" +
                                               std::to_string(animation.frames - 1) + ")");
        fitted.scene.animation = animation;
        fitted.scene = sceneAtFrame(fitted.scene, *options.frame);
    }
    checkTimeStepsFit(fitted.scene, fitted.series.size(), options.inputs.front());
    return fitted;
}

SceneOnSeries fittedSceneFor(const RenderOptions& options, SceneAndSeries opened) {
    return atRequestedFrame(options, fittedScene(options, std::move(opened)));
}

void warnAboutCutShortRays(const RenderOptions& options, const Renderer& renderer, const HeadlessContext& context) {
    if (const std::uint32_t cutShort = renderer.lastCutShortRays(); cutShort > 0)
        std::cerr << "warning: " << options.inputs.front().string() << ": " << cutShort << " of the image's rays were cut short "
                  << "by the OpenGL driver's limit on loop passes per pixel (" << context.description()
                  << "), so those pixels are incomplete; a larger raycast.step takes fewer samples per ray\n";
}

int runRender(const RenderOptions& options) {
    requireWritableImagePath(options.output, "-o");
    parseGpuMemoryOption(options.gpuMemory);
    SceneOnSeries fitted =
        fittedSceneFor(options, openSceneOrDataset(options.inputs, options.datasetFiles, options.dataset));
    const Series& series = fitted.series;
    const auto context = createHeadlessContext(parseBackend(options.gl.backend), glDebugOutputRequested());
    Renderer renderer(ShaderLibrary::fromEnvironment(options.gl.shaderDirectory));
    uploadWithinGpuMemory(renderer, series, options.gpuMemory, options.dataset);
    const auto start = std::chrono::steady_clock::now();
    AnnotatedRendering rendering(renderer, fitted);
    const Image image = rendering.render(fitted.scene);
    const double milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    writeImage(image, options.output);
    warnAboutCutShortRays(options, renderer, *context);
    std::cout << "wrote " << options.output.string() << " (" << fitted.scene.width << "x" << fitted.scene.height
              << ", " << toString(fitted.scene.compositor)
              << (fitted.scene.rayMode == kCompositeRay ? "" : ", " + toString(fitted.scene.rayMode) + " ray") << ", "
              << series.size() << " time-steps, " << milliseconds
              << " ms incl. shader compilation; " << context->description() << ")\n";
    return kExitSuccess;
}

// --distributed: every process reads the scene and its block of the series (or the whole series,
// keeping its block), renders it; the frames meet on process 0, which writes the image
// (docs/scaling.md).
int runDistributedRender(const RenderOptions& options) {
    const MpiSession mpi;
    std::optional<DistributedSource> source;
    std::optional<SceneOnSeries> fitted;
    std::optional<SceneOnSeries> outline;  // where blocks are read: the scene on the series' outline
    mpi.together("reading the scene and the series", [&] {
        if (mpi.isFirst()) requireWritableImagePath(options.output, "-o");
        parseGpuMemoryOption(options.gpuMemory);
        source = openDistributedSource(options.inputs, options.datasetFiles, options.dataset);
        fitted = fittedScene(options, std::move(source->opened));
        if (source->blockManifest) {
            outline = fitted;  // no values: small
            atRequestedFrame(options, *outline);  // --frame and the steps checked before any block is read
        } else {
            fitted = atRequestedFrame(options, std::move(*fitted));
        }
    });
    std::unique_ptr<HeadlessContext> context;
    std::optional<Renderer> renderer;
    mpi.together("starting OpenGL", [&] {
        context = createHeadlessContext(parseBackend(options.gl.backend), glDebugOutputRequested());
        renderer.emplace(ShaderLibrary::fromEnvironment(options.gl.shaderDirectory));
    });
    const std::size_t timeSteps = fitted->series.size();
    const std::string reading = readingText(*source, fitted->series);
    DistributedRendering rendering = startDistributedRendering(
        mpi, *renderer, std::move(*fitted), *source, options.dataset, [&](const Series& block, const WholeSeries& whole) {
            uploadWithinGpuMemory(*renderer, block, options.gpuMemory, options.dataset, whole);
        });
    Scene scene = rendering.scene();
    if (outline)
        // The scene's value-dependent parts came from the blocks; the frame asked for follows them.
        mpi.together("choosing the frame", [&] {
            scene = atRequestedFrame(options, {rendering.scene(), outline->series, outline->frame, rendering.framed()}).scene;
        });
    const Image image = rendering.render(scene);
    const double renderMs = mpi.maximum(rendering.lastTimes().render);
    const double compositeMs = mpi.maximum(rendering.lastTimes().composite);
    const double blockVoxels = mpi.maximum(double(rendering.blockVoxelCount()));
    const double blockBytes = mpi.maximum(double(renderer->seriesTextureBytes()));
    const double peakBytes = mpi.maximum(double(peakResidentBytes()));
    if (!mpi.isFirst()) return kExitSuccess;
    writeImage(image, options.output);
    warnAboutCutShortRays(options, *renderer, *context);
    std::cout << "wrote " << options.output.string() << " (" << scene.width << "x" << scene.height << ", "
              << toString(scene.compositor) << ", " << timeSteps << " time-steps, " << mpi.processCount()
              << " processes: render " << renderMs << " ms incl. shader compilation, composite " << compositeMs
              << " ms (slowest process); largest block " << blockVoxels << " voxels, " << blockBytes / (1024.0 * 1024.0)
              << " MiB of textures, peak memory " << peakBytes / (1024.0 * 1024.0) << " MiB (largest process); "
              << reading << "; " << context->description() << ")\n";
    return kExitSuccess;
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command = app.add_subcommand(
        "render", "Render a scene file, or a dataset with the automatic scene, to an image (PNG, TIFF, EXR)");
    command
        ->add_option("input", options->inputs,
                     std::string("A scene file (JSON); or a dataset, drawn with the automatic scene "
                                 "(docs/automatic-scene.md): ") + datasetKindsText())
        ->required();
    command->add_option("-o,--output", options->output, "Image file to write; the format follows the extension")
        ->required();
    addImageSizeOptions(*command, "Image", options->width, options->height);
    addSceneOverrides(*command, options->overrides);
    command->add_option("--style", options->styleOverrides,
                        "NAME=FILE: use this image (any format OpenImageIO reads) wherever the scene uses style NAME");
    addGlOptions(*command, options->gl);
    command->add_option("--dataset", options->datasetFiles,
                        std::string("Render this dataset instead of the scene's (repeated or comma-separated): ") +
                            datasetKindsText())
        ->delimiter(',');
    addDatasetOptions(*command, options->dataset);
    addGpuMemoryOption(*command, options->gpuMemory);
    command->add_option("--frame", options->frame,
                        "Render frame K of the scene's animation (or of the presets below), as `animate` draws it")
        ->check(CLI::Range(0, 1000000));
    addAnimationOptions(*command, options->animation);
    addAnnotationOptions(*command, options->annotations);
    command->add_flag("--distributed", options->distributed,
                      "Sort-last rendering over the MPI processes this runs in (mpirun -np N tstyles render ... "
                      "--distributed): each keeps one block of the series (docs/scaling.md)");
    return {command, [options] { return options->distributed ? runDistributedRender(*options) : runRender(*options); }};
}

}  // namespace tstyles::cli
