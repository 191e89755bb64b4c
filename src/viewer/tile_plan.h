// How a full-resolution frame is refined progressively: split into tiles the size of the coarse
// preview, each rendered through a projection cropped to its pixels. Every pass then renders at
// the same size, and the finished mosaic is the frame `tstyles render` draws in one pass. GL-free.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "tstyles/scene/camera.h"

namespace tstyles::viewer {

// A window of pixels of the full frame, origin at the bottom left (as OpenGL counts).
struct PixelWindow {
    glm::ivec2 offset{0};
    glm::ivec2 size{0};
    bool operator==(const PixelWindow&) const = default;
};

// The size of one tile (and of the coarse preview) when the frame is divided `divisor` times in
// each direction: every tile is the same size, the last row and column may reach past the frame.
glm::ivec2 tileSizeFor(glm::ivec2 frame, int divisor);

// divisor x divisor tiles covering the frame, the ones nearest the centre first (where the data
// usually is, so the interesting part sharpens first).
std::vector<PixelWindow> planTiles(glm::ivec2 frame, int divisor);

// The projection that shows only `window` of a `frame`-sized image, rendered into a target of the
// window's size: the same rays through the same pixel centres as the full projection.
glm::dmat4 cropProjection(const glm::dmat4& projection, glm::ivec2 frame, const PixelWindow& window);

// The view that shows only `window` of the frame: the cropped projection, and the window's own
// vertical field of view (the renderer sizes a pixel from it, e.g. for reading lit-sphere styles;
// a tile's pixels must count as the frame's pixels, not as pixels of a whole image of tile size).
View cropView(const View& view, glm::ivec2 frame, const PixelWindow& window);

// The divisor that should make a preview take about `targetMs`, given that the last one took
// `lastMs` at `lastDivisor` (render time grows with the pixel count).
int previewDivisorFor(double lastMs, int lastDivisor, double targetMs, int maxDivisor);

// Previews march with at least this multiple of the scene's step.
inline constexpr float kPreviewStepScale = 2.0f;
// The multiple of the scene's step a preview of `divisor` marches with: kPreviewStepScale, or half
// the divisor where that is longer (8 at 1/16). A preview pixel stands for divisor x divisor frame
// pixels, and fewer pixels stop paying on a CPU rasterizer long before the rays' length does: a
// 61 x 31 preview of the sonar's long rays is one of llvmpipe's 64-pixel bins, which one thread
// draws. Opacity correction keeps a longer step's opacities.
float previewStepScaleFor(int divisor);

}  // namespace tstyles::viewer
