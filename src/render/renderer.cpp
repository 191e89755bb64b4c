// The renderer façade: series upload, transfer-table updates and the two passes of a frame.
#include "tstyles/render/renderer.h"

#include <cmath>
#include <stdexcept>

#include "tstyles/data/coarser_series.h"
#include "tstyles/gl/cpu_rasterizer.h"
#include "tstyles/gl/gl_loader.h"
#include "tstyles/render/covered_pixels.h"
#include "tstyles/render/shader_contract.h"
#include "tstyles/scene/temporal_change.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

// How far apart neighbouring pixels read the lit sphere, in style-image units: a pixel's world
// footprint at the target's distance over the diameter of a curved feature. Real curvature is not
// known per sample; features are taken to be 16 voxels in radius, the scale at which central
// differences give smooth normals on our data. Thin style details then stay free of aliasing
// without blurring the styles of large bodies.
double styleFootprint(const View& view, int imageHeight, double finestSpacing) {
    // The height the image shows at the target, from the projection as drawn (a picture moved and
    // shrunk beside the annotations shows more).
    const double distance = glm::length(view.target - view.eye);
    const double shownHeight =
        2.0 * (view.projection == Projection::Perspective ? distance : 1.0) / view.projectionMatrix[1][1];
    const double pixelFootprint = shownHeight / imageHeight;
    const double featureRadius = 16.0 * finestSpacing;
    return pixelFootprint / (2.0 * featureRadius);
}

// The uniforms of the options that `compositor` (the variant's) takes, with the scene's values: a
// time-step pair checked against the series, a choice as its place.
std::vector<ModuleOptionUniform> compositorOptionUniforms(TemporalCompositor compositor, const Scene& scene,
                                                              std::size_t timeStepCount) {
    std::vector<ModuleOptionUniform> uniforms;
    for (const CompositorOption& option : compositorInfo(compositor).options) {
        switch (option.kind) {
            case CompositorOptionKind::Number:
                uniforms.push_back({option.uniform, float(scene.compositorOptions.number(option))});
                break;
            case CompositorOptionKind::TimeStepPair:
                uniforms.push_back({option.uniform, scene.compositorOptions.timeStepsOn(option, timeStepCount)});
                break;
            case CompositorOptionKind::Choice:
                uniforms.push_back({option.uniform, int(scene.compositorOptions.choice(option))});
                break;
        }
    }
    return uniforms;
}

// A list option's uniform is a vec4.
constexpr bool rayModeListsFitVec4() {
    for (const RayModeInfo& info : kRayModes)
        for (const RayModeOption& option : info.options)
            if (option.kind == RayModeOptionKind::NumberList && option.maxCount > 4) return false;
    return true;
}
static_assert(rayModeListsFitVec4(), "a ray mode's list option holds more numbers than its vec4 uniform");

// The uniforms of the options that `mode` (the variant's) takes, with the scene's values: a list of
// numbers as a vec4, padded with the option's padding.
std::vector<ModuleOptionUniform> rayOptionUniforms(RayMode mode, const Scene& scene) {
    std::vector<ModuleOptionUniform> uniforms;
    for (const RayModeOption& option : rayModeInfo(mode).options) {
        if (option.kind == RayModeOptionKind::Number) {
            uniforms.push_back({option.uniform, float(scene.rayOptions.number(option))});
            continue;
        }
        glm::vec4 packed(float(option.padding));
        const std::vector<double> numbers = scene.rayOptions.numbers(option);
        for (std::size_t i = 0; i < numbers.size() && i < 4; ++i) packed[int(i)] = float(numbers[i]);
        uniforms.push_back({option.uniform, packed});
    }
    return uniforms;
}

// Whether a compositor's change over time (TemporalCharacteristic.change) is at most the range of
// the densities at the sample, where every time-step there has data (brickChangeBounds): the range
// itself for the compositors that pick a time-step, and for the gradient TSTF's values whose
// automatic range is the largest change (the change, half of it for a spread, a difference); not
// a trend per unit of time, nor the scene's own code.
bool changeWithinDensityRange(TemporalCompositor compositor) {
    if (compositor == kCustomCompositor) return false;
    const TemporalCompositorInfo& info = compositorInfo(compositor);
    if (info.takesUnchanged) return true;
    return info.reads == CompositorReads::GradientTstf && info.range != AutomaticRange::SignedPerTime;
}

}  // namespace

Renderer::Renderer(ShaderLibrary shaders)
    : shaders_(std::move(shaders)),
      cpuRasterizer_(isCpuRasterizer(currentGlRenderer())),
      gradients_(shaders_, cpuRasterizer_),
      entryExitBuffers_(shaders_),
      raycaster_(shaders_) {}

void Renderer::setSeries(const Series& series, const std::optional<WholeSeries>& whole) {
    gradients_.startSeries(std::nullopt);
    gpuSeries_.reset();  // free the old atlas before allocating the new one
    gpuSeries_.emplace(series);
    follow(series, whole);
}

GpuResidency Renderer::setSeries(const Series& series, const GpuMemoryLimits& limits,
                                 const std::optional<WholeSeries>& whole) {
    GpuResidency residency = fitToGpuMemory(series, limits);
    gradients_.startSeries(limits);
    gpuSeries_.reset();
    if (residency.scale != 1.0) gpuSeries_.emplace(coarserSeries(series, residency.scale), residency.storage);
    else gpuSeries_.emplace(series, residency.storage);
    residency.chosenBytes = gpuSeries_->textureBytes();
    follow(series, whole);
    return residency;
}

void Renderer::follow(const Series& series, const std::optional<WholeSeries>& whole) {
    occupancyStale_ = true;
    worldBounds_ = series.worldBounds();
    finestSpacing_ = whole ? whole->finestSpacing : series.finestSpacing();
    latticeBounds_ = whole ? whole->bounds : worldBounds_;
}

double Renderer::stepLengthFor(const Scene& scene) const {
    return scene.raycast.step.value_or(0.5 * finestSpacing_);
}

void Renderer::draw(const Scene& scene, const View& view, const FrameOptions& options) {
    if (!gpuSeries_) throw std::logic_error("Renderer::draw without a series");
    const glm::mat4 viewProjection = glm::mat4(view.projectionMatrix * view.viewMatrix);
    const glm::mat4 inverseViewProjection = glm::mat4(glm::inverse(view.projectionMatrix * view.viewMatrix));

    const bool stfChanged =
        transferTables_.update(scene.stf, scene.indexTstf, scene.gradientTstf, gpuSeries_->timeStepCount());
    if (stfChanged || occupancyStale_) {
        gpuSeries_->updateOccupancy(transferTables_.stfEntries());
        occupancyStale_ = false;
    }
    gpuSeries_->bind();
    transferTables_.bind();
    styleTextures_.update({&scene.stf.curve, &scene.indexTstf.curve, &scene.gradientTstf.curve});
    styleTextures_.bind();
    if (options.timePasses && !passClocks_)
        passClocks_.emplace(std::array{PassClock(cpuRasterizer_), PassClock(cpuRasterizer_)});
    if (options.timePasses) (*passClocks_)[0].start();
    entryExitBuffers_.render(*gpuSeries_, viewProjection, inverseViewProjection, options.size);
    if (options.timePasses) (*passClocks_)[0].stop();

    target_.resize(options.size);
    target_.bind();
    entryExitBuffers_.bind();
    RaycastVariant variant = variantFor(scene, options);
    const RaycastParameters parameters = parametersFor(scene, view, options, variant);
    // Rays through pixels outside the series' projected bounds meet no time-step and would give
    // the background: clear to it and raycast only the rectangle that can differ.
    const glm::vec4 premultipliedBackground(glm::vec3(parameters.background) * parameters.background.a,
                                            parameters.background.a);
    glDisable(GL_SCISSOR_TEST);
    glClearNamedFramebufferfv(target_.framebufferId(), GL_COLOR, 0, &premultipliedBackground.x);
    Bounds rendered = worldBounds_;
    if (options.clipBox) {
        rendered.lower = glm::max(rendered.lower, options.clipBox->lower);
        rendered.upper = glm::max(rendered.lower, glm::min(rendered.upper, options.clipBox->upper));
    }
    const PixelRectangle covered = coveredPixels(rendered, view.projectionMatrix * view.viewMatrix, options.size);
    glEnable(GL_SCISSOR_TEST);
    glScissor(covered.offset.x, covered.offset.y, covered.size.x, covered.size.y);
    if (options.timePasses) (*passClocks_)[1].start();
    raycaster_.draw(variant, parameters);
    if (options.timePasses) (*passClocks_)[1].stop();
    glDisable(GL_SCISSOR_TEST);
    lastVariant_ = std::move(variant);
}

RaycastVariant Renderer::variantFor(const Scene& scene, const FrameOptions& options) {
    RaycastVariant variant;
    variant.compositor = scene.compositor;
    variant.rayMode = scene.rayMode;
    if (const auto& custom = scene.compositorOptions.custom; scene.compositor == kCustomCompositor && custom) {
        variant.customCode = custom->glsl;
        variant.customCodeName = custom->ownFile ? custom->origin.string() : custom->origin.string() + ": compositor.glsl";
        variant.customReads = custom->reads;
    }
    variant.collectStatistics = options.collectStatistics;
    variant.masks = gpuSeries_->hasMasks();
    variant.missingValues = gpuSeries_->hasMissingValues();
    variant.allAffine = gpuSeries_->allAffine();
    variant.unevenAxes = gpuSeries_->hasUnevenAxes();
    variant.unevenAxisWalk = gpuSeries_->hasCrowdedUnevenAxes();
    variant.beamGrids = gpuSeries_->hasBeamGrids();
    variant.rectilinearGrids = gpuSeries_->hasRectilinearGrids();
    variant.evenBeams = gpuSeries_->allBeamsEven();
    variant.structuredGrids = gpuSeries_->structuredGrids().layerCount() > 0;
    variant.styledTracks = styleTextures_.styledTrackBits();
    variant.singleNodeStyleTracks = styleTextures_.singleNodeTrackBits();
    variant.timeStepCapacity = timeStepCapacityFor(int(gpuSeries_->timeStepCount()));
    // The largest-change ray mode compares the range that the picking compositors measure for
    // unchanged places: they measure it for that mode whether or not the scene asks for them.
    variant.unchangedTime = (scene.compositorOptions.unchanged.has_value() || rayModeInfo(scene.rayMode).readsChange) &&
                            compositorInfo(scene.compositor).takesUnchanged;
    variant.stfOpacityRises = variant.unchangedTime && options.rankByDensity && transferTables_.stfOpacityRises();
    // The walk: the packed groups where the series has a packed atlas and the frame takes it.
    const PackedAlignedAtlas* packed = gpuSeries_->packedAtlas();
    if (options.naive) {
        variant.walk = TimeStepWalk::Naive;
    } else if (packed && options.packAligned) {
        variant.walk = TimeStepWalk::PackedGroups;
        variant.packedValidity = packed->validity();
        variant.packedGroupMasks = packed->hasGroupMasks();
    } else {
        variant.walk = TimeStepWalk::RayList;
    }
    const double emptyBrickShare = variant.walk == TimeStepWalk::PackedGroups ? gpuSeries_->emptyPackedBrickFraction()
                                                                              : gpuSeries_->emptyBrickFraction();
    variant.skipEmptyBricks = options.emptyBrickTest.value_or(skipsEmptyBricks(emptyBrickShare));
    variant.skipUnchangingBricks = options.skipUnchangingBricks && rayModeInfo(scene.rayMode).readsChange &&
                                   variant.walk == TimeStepWalk::PackedGroups && packed->boundsChange() &&
                                   changeWithinDensityRange(scene.compositor);
    variant.perRayCaches = options.perRayCaches.value_or(cpuRasterizer_);
    variant.precomputedGradients = gradients_.useFor(*gpuSeries_, variant.styled(), options.precomputedGradients);
    return partOf(variant, options.raycastPart);
}

RaycastParameters Renderer::parametersFor(const Scene& scene, const View& view, const FrameOptions& options,
                                          const RaycastVariant& variant) const {
    RaycastParameters parameters;
    parameters.inverseViewProjection = glm::mat4(glm::inverse(view.projectionMatrix * view.viewMatrix));
    parameters.viewport = options.size;
    parameters.timeStepCount = int(gpuSeries_->timeStepCount());
    parameters.atlasSize = gpuSeries_->layout().size;
    parameters.stepLength = float(stepLengthFor(scene) * options.stepScale);
    parameters.referenceLength = float(finestSpacing_);
    parameters.terminationOpacity = float(scene.raycast.termination);
    parameters.background = glm::vec4(scene.background);
    parameters.finalMode = scene.finalMode;
    parameters.changeRange = glm::vec2(float(scene.gradientTstf.rangeLow), float(scene.gradientTstf.rangeHigh));
    parameters.compositorOptions = compositorOptionUniforms(variant.compositor, scene, gpuSeries_->timeStepCount());
    parameters.rayOptions = rayOptionUniforms(variant.rayMode, scene);
    parameters.stfVisibleRange = transferTables_.stfVisibleRange();
    if (variant.unchangedTime) {
        // Without the scene's option (the largest-change mode alone): only places whose densities
        // do not change at all, or tie exactly, show no time colour.
        const UnchangedTime unchanged = scene.compositorOptions.unchanged.value_or(UnchangedTime{});
        static_assert(kUnchangedDensityBands == contract::UNCHANGED_DENSITY_BANDS);
        for (int band = 0; band < contract::UNCHANGED_DENSITY_BANDS; ++band) {
            const auto at = std::size_t(band);
            parameters.unchangedBelow[at] =
                float(unchanged.belowByDensity.size() > at ? unchanged.belowByDensity[at] : unchanged.below);
            parameters.unchangedTie[at] =
                float(unchanged.tieByDensity.size() > at ? unchanged.tieByDensity[at] : unchanged.tie);
        }
        // Where one sample makes the pixel (a projection) the gain, which thickens the changing part
        // of a composited ray, and the fading of regions, which lets compositing see through them,
        // have nothing to act on: the unchanged places show at their share of the STF's opacity.
        const bool projection = rayModeInfo(variant.rayMode).pixelTakesStfOpacity;
        parameters.changedGain = projection ? 1.0f : float(unchanged.gain);
        parameters.unchangedBoundary = projection ? 0.0f : float(unchanged.boundary);
        parameters.unchangedOpacity = float(unchanged.opacity);
    }
    parameters.exposedSteps = options.soloTimeStep ? glm::ivec2(*options.soloTimeStep)
                                                   : scene.exposure.stepsOf(gpuSeries_->timeStepCount());
    if (variant.walk == TimeStepWalk::PackedGroups) {
        const PackedAlignedAtlas& packed = *gpuSeries_->packedAtlas();
        parameters.sharedValiditySize = packed.sharedValiditySize();
        parameters.packedGroupCount = packed.groupCount();
        parameters.packedAtlasSize = packed.layout().size;
    }
    parameters.styleTracks = styleTextures_.trackRanges();
    parameters.worldToView = glm::mat3(view.viewMatrix);
    parameters.styleFootprint = float(styleFootprint(view, options.size.y, finestSpacing_));
    parameters.seriesLower = glm::vec3(latticeBounds_.lower);
    parameters.seriesUpper = glm::vec3(latticeBounds_.upper);
    if (options.clipBox) {
        parameters.clipLower = glm::vec3(options.clipBox->lower);
        parameters.clipUpper = glm::vec3(options.clipBox->upper);
    }
    return parameters;
}

FramePassTimes Renderer::lastPassTimes() const {
    if (!passClocks_) throw std::logic_error("Renderer::lastPassTimes without a frame drawn with timePasses");
    return {(*passClocks_)[0].milliseconds(), (*passClocks_)[1].milliseconds()};
}

std::size_t Renderer::seriesTextureBytes() const {
    return gpuSeries_ ? gpuSeries_->textureBytes() + gradientTextureBytes() : 0;
}

std::size_t Renderer::frameTextureBytes() const {
    return entryExitBuffers_.textureBytes() + std::size_t(target_.size().x) * std::size_t(target_.size().y) * 16;
}

Image renderImage(Renderer& renderer, const Scene& scene, const Bounds& seriesBounds) {
    return renderImage(renderer, scene, seriesBounds, seriesBounds);
}

Image renderImage(Renderer& renderer, const Scene& scene, const Bounds& framed, const Bounds& seriesBounds) {
    const View view = resolveView(scene.camera, framed, seriesBounds, scene.width, scene.height);
    FrameOptions options;
    options.size = {scene.width, scene.height};
    renderer.draw(scene, view, options);
    return renderer.readFrame();
}

}  // namespace tstyles
