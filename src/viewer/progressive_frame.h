// What the volume area shows: on every change a coarse preview (fewer pixels, longer ray steps)
// is drawn at once, then, while nobody is dragging, the full-quality frame is built tile by tile
// within a time budget per UI frame, so the window stays responsive on a CPU rasterizer. The
// finished frame is the one `tstyles render` draws for the same scene and size.
#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tile_plan.h"
#include "tstyles/gl/objects.h"
#include "tstyles/render/render_target.h"
#include "tstyles/render/renderer.h"
#include "tstyles/scene/scene.h"

namespace tstyles::viewer {

// A preview should take about this long, so that dragging stays near 15 frames per second with
// the UI's own drawing on top.
inline constexpr double kPreviewTargetMs = 45.0;
// Refinement renders tiles until this much of a UI frame is used.
inline constexpr double kRefineBudgetMs = 40.0;
inline constexpr int kMaxPreviewDivisor = 16;
// Tiles are never smaller than this on either side: a rasterizer works in bins (llvmpipe's are
// 64 pixels square) and spreads them over its threads, so a tinier tile is no faster.
inline constexpr int kMinTileSide = 64;

// What an update did (for the frame statistics).
enum class FrameWork { None, Preview, Refinement };

class ProgressiveFrame {
public:
    // Brings the frame up to date: a new preview if the scene, size or solo time-step changed,
    // else more tiles unless the user is interacting. Needs the renderer's series set.
    FrameWork update(Renderer& renderer, const Scene& scene, const Bounds& bounds, glm::ivec2 size,
                std::optional<int> soloTimeStep, bool interacting);
    // Forget what was drawn (a new series): the next update starts over.
    void invalidate() { drawn_.reset(); }

    bool hasImage() const { return drawn_.has_value(); }
    // The full-quality frame of the latest request is complete.
    bool refined() const { return drawn_.has_value() && pending_.empty(); }
    // Fraction of the full-quality tiles done, 1 when refined.
    double progress() const;

    // Copies the frame 1:1 into the bound draw framebuffer at `offset` (pixels from bottom left).
    void present(glm::ivec2 offset) const;

    glm::ivec2 size() const { return size_; }
    int previewDivisor() const { return divisor_; }
    int tileDivisor() const { return tileDivisor_; }
    double lastPreviewMs() const { return lastPreviewMs_; }
    // Seconds from the last change to the finished frame (of the last refinement that finished).
    double lastRefinementSeconds() const { return lastRefinementSeconds_; }

private:
    struct Request {
        Scene scene;
        glm::ivec2 size{0};
        std::optional<int> soloTimeStep;
        bool operator==(const Request&) const = default;
    };

    void ensureCanvas(glm::ivec2 size);
    double renderWindow(Renderer& renderer, const Scene& scene, const View& view, const PixelWindow& window,
                        glm::ivec2 renderSize, float stepScale, std::optional<int> soloTimeStep);
    void renderPreview(Renderer& renderer, const Request& request, const View& view);

    std::optional<Request> drawn_;
    std::optional<View> view_;
    RenderTarget canvas_;  // the assembled frame, tile by tile
    glm::ivec2 size_{0};
    std::vector<PixelWindow> pending_;
    std::size_t tileCount_ = 0;
    int divisor_ = 4;
    double lastPreviewMs_ = 0.0;
    // Tiles march the full step, twice as many samples as a preview: they have a quarter of the
    // preview's pixels (half its size each way), so one takes about half as long as a preview.
    int tileDivisor_ = 8;
    std::chrono::steady_clock::time_point changedAt_{};
    double lastRefinementSeconds_ = 0.0;
};

}  // namespace tstyles::viewer
