// The renderer façade: series upload, transfer-table updates and the two passes of a frame.
#include "tstyles/render/renderer.h"

#include <stdexcept>

namespace tstyles {

Renderer::Renderer(ShaderLibrary shaders)
    : shaders_(std::move(shaders)), entryExitBuffers_(shaders_), raycaster_(shaders_) {}

void Renderer::setSeries(const Series& series) {
    gpuSeries_.reset();  // free the old atlas before allocating the new one
    gpuSeries_.emplace(series);
    finestSpacing_ = series.finestSpacing();
}

double Renderer::stepLengthFor(const Scene& scene) const {
    return scene.raycast.step.value_or(0.5 * finestSpacing_);
}

void Renderer::draw(const Scene& scene, const View& view, const FrameOptions& options) {
    if (!gpuSeries_) throw std::logic_error("Renderer::draw without a series");
    const glm::mat4 viewProjection = glm::mat4(view.projectionMatrix * view.viewMatrix);
    const glm::mat4 inverseViewProjection = glm::mat4(glm::inverse(view.projectionMatrix * view.viewMatrix));

    gpuSeries_->bind();
    transferTables_.update(scene.stf, scene.indexTstf, scene.gradientTstf, gpuSeries_->timeStepCount());
    transferTables_.bind();
    entryExitBuffers_.render(*gpuSeries_, viewProjection, inverseViewProjection, options.size);

    target_.resize(options.size);
    target_.bind();
    entryExitBuffers_.bind();
    RaycastParameters parameters;
    parameters.inverseViewProjection = inverseViewProjection;
    parameters.viewport = options.size;
    parameters.timeStepCount = int(gpuSeries_->timeStepCount());
    parameters.atlasSize = gpuSeries_->layout().size;
    parameters.stepLength = float(stepLengthFor(scene) * options.stepScale);
    parameters.referenceLength = float(finestSpacing_);
    parameters.terminationOpacity = float(scene.raycast.termination);
    parameters.background = glm::vec4(scene.background);
    parameters.compositor = scene.compositor;
    parameters.finalMode = scene.finalMode;
    parameters.changeRange = glm::vec2(float(scene.gradientTstf.rangeLow), float(scene.gradientTstf.rangeHigh));
    parameters.collectStatistics = options.collectStatistics;
    parameters.soloTimeStep = options.soloTimeStep.value_or(-1);
    raycaster_.draw(parameters);
}

std::size_t Renderer::seriesTextureBytes() const { return gpuSeries_ ? gpuSeries_->textureBytes() : 0; }

std::size_t Renderer::frameTextureBytes() const {
    return entryExitBuffers_.textureBytes() + std::size_t(target_.size().x) * std::size_t(target_.size().y) * 16;
}

Image renderImage(Renderer& renderer, const Scene& scene, const Bounds& seriesBounds) {
    const View view = resolveView(scene.camera, seriesBounds, scene.width, scene.height);
    FrameOptions options;
    options.size = {scene.width, scene.height};
    renderer.draw(scene, view, options);
    return renderer.readFrame();
}

}  // namespace tstyles
