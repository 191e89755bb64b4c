// `tstyles animate SCENE -o OUT`: an animation sequence rendered headless into a movie (MP4, WebM,
// GIF) or a folder of numbered frames, with progress, and nothing half-written on error or Ctrl+C.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "animation_options.h"
#include "annotation_options.h"
#include "batch_frame_options.h"
#include "tstyles/render/annotated_rendering.h"
#include "commands.h"
#include "distributed_source.h"
#include "gpu_memory_option.h"
#include "frame_sink.h"
#include "interrupt_guard.h"
#include "progress_bar.h"
#include "scene_source.h"
#include "tstyles/core/errors.h"
#include "tstyles/distributed/distributed_rendering.h"
#include "tstyles/render/renderer.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles::cli {
namespace {

struct AnimateOptions {
    std::vector<std::filesystem::path> inputs;
    std::filesystem::path output;
    std::optional<int> width;
    std::optional<int> height;
    AnimationOptions animation;
    AnnotationOptions annotations;
    SceneOverrides overrides;
    GlOptions gl;
    DatasetOptions dataset;
    GpuMemoryOption gpuMemory;
    bool distributed = false;  // --distributed: every frame sort-last over the MPI processes
};

// Every frame's scene, made before anything is rendered: a key that leaves the scene's allowed
// values, or an exposure the series cannot give, fails before any work.
std::vector<Scene> frameScenes(const Scene& scene, std::size_t stepCount, const std::filesystem::path& input) {
    std::vector<Scene> scenes;
    scenes.reserve(std::size_t(scene.animation.frames));
    for (int frame = 0; frame < scene.animation.frames; ++frame) {
        Scene atFrame = sceneAtFrame(scene, frame);
        try {
            atFrame.exposure.stepsOf(stepCount);
        } catch (const InputError& error) {
            throwInputError(input, "animation", "at frame " + std::to_string(frame) + ": " + error.what());
        }
        scenes.push_back(std::move(atFrame));
    }
    return scenes;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// The fitted scene with its animation, and every frame's scene.
struct AnimationPlan {
    SceneOnSeries fitted;
    MovieSettings movie;
    std::vector<Scene> scenes;
};

// The scene the options ask for (`opened`: with its series), fitted to the series, before its
// animation is made.
SceneOnSeries fittedForAnimation(const AnimateOptions& options, SceneAndSeries opened) {
    Scene& scene = opened.scene;
    if (options.width) scene.width = *options.width;
    if (options.height) scene.height = *options.height;
    applySceneOverrides(opened, options.overrides);
    applyAnnotationOptions(scene, options.annotations);
    return fitSceneToSeries(std::move(scene), std::move(opened.series));
}

// The animation of `fitted` (the scene's, or the presets') and its frames.
AnimationPlan planFrames(const AnimateOptions& options, SceneOnSeries fitted, bool checkOutput) {
    const std::string sceneName = options.inputs.front().string();
    fitted.scene.animation =
        animationFor(fitted.scene, fitted.series.size(), options.animation, sceneName, cameraDistance(fitted));
    const MovieSettings movie{fitted.scene.width, fitted.scene.height, fitted.scene.animation.framesPerSecond};
    if (checkOutput) requireWritableFrameOutput(options.output, movie);
    std::vector<Scene> scenes = frameScenes(fitted.scene, fitted.series.size(), options.inputs.front());
    return {std::move(fitted), movie, std::move(scenes)};
}

AnimationPlan planAnimation(const AnimateOptions& options, SceneAndSeries opened, bool checkOutput) {
    return planFrames(options, fittedForAnimation(options, std::move(opened)), checkOutput);
}

void reportWritten(const AnimateOptions& options, const FrameSink& sink, const MovieSettings& movie,
                   const std::vector<double>& milliseconds, const std::string& how) {
    std::cout << "wrote " << options.output.string() << " (" << sink.description() << ", " << movie.width << "x"
              << movie.height << " at " << sink.framesPerSecond() << " fps; median " << median(milliseconds)
              << " ms per frame; " << how << ")\n";
}

int runAnimate(const AnimateOptions& options) {
    parseGpuMemoryOption(options.gpuMemory);
    AnimationPlan plan = planAnimation(options, openSceneOrDataset(options.inputs, {}, options.dataset), true);
    SceneOnSeries& fitted = plan.fitted;
    const MovieSettings& movie = plan.movie;
    const std::vector<Scene>& scenes = plan.scenes;
    const auto context = createHeadlessContext(parseBackend(options.gl.backend), glDebugOutputRequested());
    Renderer renderer(ShaderLibrary::fromEnvironment(options.gl.shaderDirectory));
    uploadWithinGpuMemory(renderer, fitted.series, options.gpuMemory, options.dataset);
    AnnotatedRendering rendering(renderer, fitted);
    // From before the output is opened: a Ctrl+C after it is caught and ends with nothing written.
    const InterruptGuard interrupt;
    std::unique_ptr<FrameSink> sink = openFrameSink(options.output, movie);
    ProgressBar progress("rendering frame", int(scenes.size()));
    std::vector<double> milliseconds;
    for (std::size_t frame = 0; frame < scenes.size(); ++frame) {
        if (interrupt.interrupted()) {
            progress.finish();
            std::cerr << "tstyles: interrupted; " << options.output.string() << " was not written\n";
            return kExitInterrupted;
        }
        progress.update(int(frame));
        const auto start = std::chrono::steady_clock::now();
        sink->add(rendering.render(scenes[frame], asOneFrameRenderDrawsIt()));
        milliseconds.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    progress.update(int(scenes.size()));
    progress.finish();
    sink->finish();
    reportWritten(options, *sink, movie, milliseconds, context->description());
    return kExitSuccess;
}

// --distributed: every frame is rendered by all processes, each its block of the series, and
// composited onto process 0, which writes the movie (docs/scaling.md).
int runDistributedAnimate(const AnimateOptions& options) {
    const MpiSession mpi;
    std::optional<AnimationPlan> plan;
    std::optional<DistributedSource> source;
    std::optional<SceneOnSeries> unanimated;  // where blocks are read: the outline's scene before its animation
    mpi.together("reading the scene and the series", [&] {
        parseGpuMemoryOption(options.gpuMemory);
        source = openDistributedSource(options.inputs, {}, options.dataset);
        SceneOnSeries fitted = fittedForAnimation(options, std::move(source->opened));
        if (source->blockManifest) unanimated = fitted;  // an outline: no values
        plan = planFrames(options, std::move(fitted), mpi.isFirst());
    });
    std::unique_ptr<HeadlessContext> context;
    std::optional<Renderer> renderer;
    mpi.together("starting OpenGL", [&] {
        context = createHeadlessContext(parseBackend(options.gl.backend), glDebugOutputRequested());
        renderer.emplace(ShaderLibrary::fromEnvironment(options.gl.shaderDirectory));
    });
    const std::string reading = readingText(*source, plan->fitted.series);
    DistributedRendering rendering = startDistributedRendering(
        mpi, *renderer, std::move(plan->fitted), *source, options.dataset,
        [&](const Series& block, const WholeSeries& whole) {
            uploadWithinGpuMemory(*renderer, block, options.gpuMemory, options.dataset, whole);
        });
    if (unanimated)
        // The plan above was the outline's (it checked the output before any block was read); the
        // frames follow the scene fitted over the blocks: its opacity, gradient range and framing.
        mpi.together("planning the frames", [&] {
            Scene scene = rendering.scene();
            scene.animation = unanimated->scene.animation;
            plan = planFrames(options, {std::move(scene), unanimated->series, unanimated->frame, rendering.framed()},
                              false);
        });
    const InterruptGuard interrupt;  // before the output is opened, as in runAnimate
    std::unique_ptr<FrameSink> sink;
    mpi.together("opening the output", [&] {
        if (mpi.isFirst()) sink = openFrameSink(options.output, plan->movie);
    });
    std::optional<ProgressBar> progress;
    if (mpi.isFirst()) progress.emplace("rendering frame", int(plan->scenes.size()));
    std::vector<double> milliseconds;
    for (std::size_t frame = 0; frame < plan->scenes.size(); ++frame) {
        // Ctrl+C reaches every process; all stop at the same frame.
        if (mpi.maximum(interrupt.interrupted() ? 1.0 : 0.0) > 0.0) {
            if (!mpi.isFirst()) return kExitSuccess;
            progress->finish();
            std::cerr << "tstyles: interrupted; " << options.output.string() << " was not written\n";
            return kExitInterrupted;
        }
        if (progress) progress->update(int(frame));
        const auto start = std::chrono::steady_clock::now();
        const Image image = rendering.render(plan->scenes[frame], asOneFrameRenderDrawsIt());
        mpi.together("writing a frame", [&] {
            if (mpi.isFirst()) sink->add(image);
        });
        milliseconds.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    mpi.together("finishing the output", [&] {
        if (mpi.isFirst()) sink->finish();
    });
    if (!mpi.isFirst()) return kExitSuccess;
    progress->update(int(plan->scenes.size()));
    progress->finish();
    reportWritten(options, *sink, plan->movie, milliseconds,
                  std::to_string(mpi.processCount()) + " processes, sort-last; " + reading + "; " +
                      context->description());
    return kExitSuccess;
}

}  // namespace

Command addAnimateCommand(CLI::App& app) {
    auto options = std::make_shared<AnimateOptions>();
    CLI::App* command = app.add_subcommand(
        "animate", "Render a scene's animation (or a preset) headless to a movie (MP4, WebM, GIF) or a frames folder");
    command
        ->add_option("input", options->inputs,
                     "A scene file (JSON) with an animation section or used with a preset; or a dataset, drawn "
                     "with the automatic scene")
        ->required();
    command
        ->add_option("-o,--output", options->output,
                     "out.mp4, out.webm, out.gif, or a folder (ending in /) for frame-0000.png, ...")
        ->required();
    addImageSizeOptions(*command, "Frame", options->width, options->height);
    addAnimationOptions(*command, options->animation);
    addAnnotationOptions(*command, options->annotations);
    addSceneOverrides(*command, options->overrides);
    addGlOptions(*command, options->gl);
    addDatasetOptions(*command, options->dataset);
    addGpuMemoryOption(*command, options->gpuMemory);
    command->add_flag("--distributed", options->distributed,
                      "Render every frame sort-last over the MPI processes this runs in (mpirun -np N tstyles "
                      "animate ... --distributed): each reads or keeps one block of the series (docs/scaling.md)");
    return {command, [options] { return options->distributed ? runDistributedAnimate(*options) : runAnimate(*options); }};
}

}  // namespace tstyles::cli
