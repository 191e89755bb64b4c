// One process's part of a sort-last frame (distributed_rendering.h).
#include "tstyles/distributed/distributed_rendering.h"

#include <chrono>
#include <optional>
#include <vector>

#include "tstyles/core/errors.h"
#include "tstyles/data/series_crop.h"
#include "tstyles/distributed/fitting_over_blocks.h"
#include "tstyles/distributed/sort_last_compositing.h"
#include "tstyles/scene/ray_modes.h"

namespace tstyles {
namespace {

// The series' times, grids and metadata without its values: what annotations read.
Series outlineOf(const Series& series) {
    Series outline = withoutTimeSteps(series);
    for (const TimeStep& step : series.steps) outline.steps.push_back(withoutValues(step));
    return outline;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

DistributedRendering::DistributedRendering(const MpiSession& mpi, Renderer& renderer, Scene scene,
                                           const Bounds& wholeBounds, const Bounds& framed, const DisplayFrame& frame)
    : mpi_(mpi),
      renderer_(renderer),
      scene_(std::move(scene)),
      blocks_(wholeBounds, mpi.processCount()),
      wholeBounds_(wholeBounds),
      framed_(framed),
      frame_(frame) {}

DistributedRendering::DistributedRendering(const MpiSession& mpi, Renderer& renderer, SceneOnSeries fitted,
                                           const BlockUpload& upload)
    : DistributedRendering(mpi, renderer, std::move(fitted.scene), fitted.series.worldBounds(), fitted.framed,
                           fitted.frame) {
    mpi_.together("keeping this process's block", [&] {
        // Every process needs the whole series' finest spacing; process 0 its outline too.
        Series outline = outlineOf(fitted.series);
        const Series block = cropSeriesToBox(std::move(fitted.series), blocks_.block(mpi_.rank()), kBlockGhostNodes);
        keepBlock(block, std::move(outline), upload);
    });
    if (mpi_.isFirst()) annotator_.emplace(outline_, framed_, frame_);
}

DistributedRendering::DistributedRendering(const MpiSession& mpi, Renderer& renderer, SceneOnSeries fittedOutline,
                                           const BlockReader& read, const BlockUpload& upload, bool automaticOpacity)
    : DistributedRendering(mpi, renderer, std::move(fittedOutline.scene), fittedOutline.series.worldBounds(),
                           fittedOutline.framed, fittedOutline.frame) {
    std::optional<BlockOfSeries> block;
    mpi_.together("reading this process's block", [&] { block = read(blocks_.block(mpi_.rank())); });
    combineRawRanges(mpi_, block->series);
    if (fittingReadsValues(scene_, automaticOpacity)) {
        SceneFittedOverBlocks fitted =
            fitOverBlocks(mpi_, blocks_, scene_, automaticOpacity, fittedOutline.series, *block, framed_);
        scene_ = std::move(fitted.scene);
        framed_ = fitted.framed;
    }
    mpi_.together("keeping this process's block", [&] {
        // The value range and each time-step's raw range come from the values, which the outline
        // has not read; every block has them of the whole series.
        Series& outline = fittedOutline.series;
        outline.valueRange = block->series.valueRange;
        for (std::size_t index = 0; index < outline.steps.size(); ++index)
            outline.steps[index].rawRange = block->series.steps[index].rawRange;
        keepBlock(block->series, std::move(outline), upload);
    });
    if (mpi_.isFirst()) annotator_.emplace(outline_, framed_, frame_);
}

void DistributedRendering::keepBlock(const Series& block, Series outline, const BlockUpload& upload) {
    const WholeSeries whole{outline.finestSpacing(), wholeBounds_};
    for (const TimeStep& step : block.steps) blockVoxels_ += gridVoxelCount(step.grid);
    upload(block, whole);
    if (mpi_.isFirst()) outline_ = std::move(outline);
}

Image DistributedRendering::render(const Scene& scene, FrameOptions options) {
    const RayModeInfo& ray = rayModeInfo(scene.rayMode);
    if (ray.merge != RayMerge::Over)
        throw InputError("ray.mode \"" + std::string(ray.name) +
                         "\": distributed rendering merges the processes' frames front to back (the over "
                         "operator), which holds for the composite ray mode only; render this scene without "
                         "--distributed");
    View view = resolveView(scene.camera, framed_, wholeBounds_, scene.width, scene.height);
    if (scene.annotations.any()) {
        // Process 0 lays the annotations out and moves the picture beside them (a new projection,
        // SceneAnnotator::viewOf); every process renders its block with that projection.
        std::vector<double> projection(16, 0.0);
        mpi_.together("laying out the annotations", [&] {
            if (!annotator_) return;
            const glm::dmat4 moved = annotator_->viewOf(scene).projectionMatrix;
            for (int column = 0; column < 4; ++column)
                for (int row = 0; row < 4; ++row) projection[std::size_t(4 * column + row)] = moved[column][row];
        });
        projection = mpi_.sum(std::move(projection));
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row) view.projectionMatrix[column][row] = projection[std::size_t(4 * column + row)];
    }
    const glm::dmat4 inverseViewProjection = glm::inverse(view.projectionMatrix * view.viewMatrix);
    Image local;
    const auto renderStart = std::chrono::steady_clock::now();
    mpi_.together("rendering this process's block", [&] {
        // Blocks are rendered over nothing; process 0 puts the background behind the composite.
        Scene blockScene = scene;
        blockScene.background = glm::dvec4(0.0);
        options.size = {scene.width, scene.height};
        options.clipBox = blocks_.block(mpi_.rank());
        renderer_.draw(blockScene, view, options);
        local = renderer_.readFrame();
    });
    lastTimes_.render = millisecondsSince(renderStart);
    const auto compositeStart = std::chrono::steady_clock::now();
    Image frame = compositeSortLast(mpi_, blocks_, local, inverseViewProjection);
    lastTimes_.composite = millisecondsSince(compositeStart);
    if (!mpi_.isFirst()) return frame;

    const glm::vec4 background(scene.background);
    const glm::vec4 behind(glm::vec3(background) * background.a, background.a);
    for (std::size_t pixel = 0; pixel < frame.rgba.size(); pixel += 4) {
        const glm::vec4 composited =
            over(glm::vec4(frame.rgba[pixel], frame.rgba[pixel + 1], frame.rgba[pixel + 2], frame.rgba[pixel + 3]), behind);
        std::copy_n(&composited.x, 4, frame.rgba.data() + pixel);
    }
    annotator_->annotate(frame, scene);
    return frame;
}

}  // namespace tstyles
