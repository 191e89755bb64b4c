// The renderer Python keeps (python_renderer.h).
#include "python_renderer.h"

#include "tstyles/core/errors.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles::python {
namespace {

std::size_t g_totalUploads = 0;

// One context per process: GL entry points are loaded process-wide from the current context, so
// two contexts of different libraries (EGL, OSMesa) cannot take turns.
struct ProcessContext {
    std::weak_ptr<HeadlessContext> context;
    GlBackend backend = GlBackend::Auto;
};
ProcessContext g_process;

std::shared_ptr<HeadlessContext> processContext(GlBackend backend) {
    if (auto existing = g_process.context.lock()) {
        if (backend != GlBackend::Auto && g_process.backend != GlBackend::Auto && backend != g_process.backend)
            throwInputError("", "backend",
                            "this process renders through " + existing->description() +
                                " already; one process holds one OpenGL context, so every Renderer shares it "
                                "(close the others first)");
        return existing;
    }
    std::shared_ptr<HeadlessContext> created = createHeadlessContext(backend, glDebugOutputRequested());
    g_process = {created, backend};
    return created;
}

}  // namespace

PythonRenderer::PythonRenderer(GlBackend backend)
    : context_(processContext(backend)),
      renderer_(std::make_unique<Renderer>(ShaderLibrary::fromEnvironment(std::nullopt))) {}

PythonRenderer::~PythonRenderer() { close(); }

void PythonRenderer::close() {
    shown_.reset();
    renderer_.reset();
    context_.reset();
}

Renderer& PythonRenderer::renderer() {
    if (!renderer_) throwInputError("", "Renderer", "is closed");
    return *renderer_;
}

std::string PythonRenderer::description() const { return context_ ? context_->description() : "closed"; }

std::uint32_t PythonRenderer::lastCutShortRays() const { return renderer_ ? renderer_->lastCutShortRays() : 0; }

// Display settings that resolve to the same turn and scale (an "auto" that chooses the data's own
// axes) show the same display series: no upload.
void PythonRenderer::show(const SharedSeries& series, const Scene& scene) {
    DisplayFrame frame = chooseDisplayFrame(scene.display, *series);
    if (shown_ && shown_->series == series && shown_->frame.rotation == frame.rotation &&
        shown_->frame.scale == frame.scale) {
        shown_->frame.explanation = std::move(frame.explanation);
        return;
    }
    Renderer& gl = renderer();
    shown_.reset();  // its display series may be large: let it go before the next is made
    Shown shown;
    shown.series = series;
    shown.frame = std::move(frame);
    shown.displaySeries =
        shown.frame.isIdentity() ? series : std::make_shared<const Series>(applyDisplayFrame(*series, shown.frame));
    gl.setSeries(*shown.displaySeries);
    ++uploads_;
    ++g_totalUploads;
    shown_ = std::move(shown);
    shown_->annotated = std::make_unique<AnnotatedRendering>(gl, *shown_->displaySeries, shown_->framed, shown_->frame);
}

// fitSceneToSeries on the kept display series; the automatic gradient range and unchanged threshold
// (a pass over every voxel) are computed again only when the STF changed.
Scene PythonRenderer::fitted(const Scene& scene) {
    Shown& shown = *shown_;
    Scene result = scene;
    const bool fitsUnchanged = scene.compositorOptions.unchanged && scene.compositorOptions.unchanged->automatic;
    if (scene.gradientTstf.automaticRange || fitsUnchanged) {
        if (!shown.gradientRangeHigh || !(shown.gradientRangeStf == scene.stf)) {
            Scene fit = scene;
            fit.gradientTstf.automaticRange = true;
            fit.compositorOptions.unchanged = UnchangedTime{};
            fit = fitAutomaticParts(fit, *shown.displaySeries);
            shown.gradientRangeHigh = fit.gradientTstf.rangeHigh;
            shown.unchangedFit = fittedOf(*fit.compositorOptions.unchanged);
            shown.gradientRangeStf = scene.stf;
        }
    }
    if (scene.gradientTstf.automaticRange) {
        result.gradientTstf.rangeLow = 0.0;
        result.gradientTstf.rangeHigh = *shown.gradientRangeHigh;
    }
    if (fitsUnchanged) takeFit(*result.compositorOptions.unchanged, shown.unchangedFit);
    shown.framed = framedBounds(result, *shown.displaySeries);
    return result;
}

Image PythonRenderer::render(const SharedSeries& series, const Scene& scene) {
    show(series, scene);
    const Scene fit = fitted(scene);
    fit.exposure.stepsOf(shown_->displaySeries->size(), series->manifestPath);
    return shown_->annotated->render(fit);
}

std::size_t totalUploads() { return g_totalUploads; }

}  // namespace tstyles::python
