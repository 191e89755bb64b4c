// Preview, tiles and the canvas they are assembled in.
#include "progressive_frame.h"

#include <algorithm>
#include <array>

#include "tstyles/gl/gl_api.h"

namespace tstyles::viewer {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

void ProgressiveFrame::ensureCanvas(glm::ivec2 size) {
    canvas_.resize(size);
    size_ = size;
}

// Renders one window of the frame at `renderSize` pixels and returns the milliseconds it took
// (waiting for the GPU, so that the budget means something).
double ProgressiveFrame::renderWindow(Renderer& renderer, const Scene& scene, const View& view,
                                      const PixelWindow& window, glm::ivec2 renderSize, float stepScale,
                                      std::optional<int> soloTimeStep) {
    const auto start = Clock::now();
    const View cropped = cropView(view, size_, window);
    FrameOptions options;
    options.size = renderSize;
    options.stepScale = stepScale;
    options.soloTimeStep = soloTimeStep;
    // The UI leaves scissoring and blending as it found them, but the raycaster must not depend
    // on that.
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    renderer.draw(scene, cropped, options);
    glBlitNamedFramebuffer(renderer.target().framebufferId(), canvas_.framebufferId(), 0, 0, renderSize.x,
                           renderSize.y, window.offset.x, window.offset.y, window.offset.x + window.size.x,
                           window.offset.y + window.size.y, GL_COLOR_BUFFER_BIT,
                           renderSize == window.size ? GL_NEAREST : GL_LINEAR);
    glFinish();
    return millisecondsSince(start);
}

void ProgressiveFrame::renderPreview(Renderer& renderer, const Request& request, const View& view) {
    const glm::ivec2 tile = tileSizeFor(size_, divisor_);
    // The preview covers the padded frame (divisor whole tiles), so each preview pixel stands for
    // exactly divisor x divisor frame pixels.
    const PixelWindow padded{{0, 0}, tile * divisor_};
    lastPreviewMs_ =
        renderWindow(renderer, request.scene, view, padded, tile, previewStepScaleFor(divisor_), request.soloTimeStep);
    const int finestDivisor = std::max(1, std::min(size_.x, size_.y) / kMinTileSide);
    tileDivisor_ = std::clamp(2 * divisor_, 1, finestDivisor);
    pending_ = planTiles(size_, tileDivisor_);
    tileCount_ = pending_.size();
}

FrameWork ProgressiveFrame::update(Renderer& renderer, const Scene& scene, const Bounds& bounds, glm::ivec2 size,
                              std::optional<int> soloTimeStep, bool interacting) {
    if (size.x <= 0 || size.y <= 0 || !renderer.hasSeries()) return FrameWork::None;
    if (!drawn_ || drawn_->size != size || drawn_->soloTimeStep != soloTimeStep || !(drawn_->scene == scene)) {
        ensureCanvas(size);
        drawn_ = Request{scene, size, soloTimeStep};
        view_ = resolveView(scene.camera, bounds, size.x, size.y);
        if (lastPreviewMs_ > 0.0)
            divisor_ = previewDivisorFor(lastPreviewMs_, divisor_, kPreviewTargetMs, kMaxPreviewDivisor);
        changedAt_ = Clock::now();
        renderPreview(renderer, *drawn_, *view_);
        return FrameWork::Preview;
    }
    if (interacting || pending_.empty()) return FrameWork::None;
    const auto start = Clock::now();
    while (!pending_.empty() && millisecondsSince(start) < kRefineBudgetMs) {
        const PixelWindow tile = pending_.front();
        pending_.erase(pending_.begin());
        renderWindow(renderer, drawn_->scene, *view_, tile, tile.size, 1.0f, drawn_->soloTimeStep);
    }
    if (pending_.empty()) lastRefinementSeconds_ = millisecondsSince(changedAt_) / 1000.0;
    return FrameWork::Refinement;
}

double ProgressiveFrame::progress() const {
    if (!drawn_) return 0.0;
    if (tileCount_ == 0) return 1.0;
    return 1.0 - double(pending_.size()) / double(tileCount_);
}

void ProgressiveFrame::present(glm::ivec2 offset) const {
    if (size_.x == 0) return;
    GLint drawFramebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
    glDisable(GL_SCISSOR_TEST);
    glBlitNamedFramebuffer(canvas_.framebufferId(), GLuint(drawFramebuffer), 0, 0, size_.x, size_.y, offset.x, offset.y,
                           offset.x + size_.x, offset.y + size_.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

}  // namespace tstyles::viewer
