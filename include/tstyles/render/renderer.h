// The renderer: turns a scene and a series into an image. Front ends (CLI, viewer, benchmark,
// tests) all go through this one type. Per-series work (upload) happens in setSeries, per-change
// work (transfer-function baking) only when the scene's functions change, per-frame work in draw.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "tstyles/data/series.h"
#include "tstyles/gl/program.h"
#include "tstyles/image/image.h"
#include "tstyles/render/entry_exit_buffers.h"
#include "tstyles/render/gpu_memory_budget.h"
#include "tstyles/render/gpu_series.h"
#include "tstyles/render/pass_clock.h"
#include "tstyles/render/precomputed_gradients.h"
#include "tstyles/render/raycaster.h"
#include "tstyles/render/render_target.h"
#include "tstyles/render/style_textures.h"
#include "tstyles/render/transfer_tables.h"
#include "tstyles/scene/scene.h"

namespace tstyles {

struct FrameOptions {
    glm::ivec2 size{512, 512};
    bool collectStatistics = false;
    // Multiplies the scene's step length (the viewer uses a coarser step while dragging).
    float stepScale = 1.0f;
    // Shows this one time-step alone (plain playback, for comparison); none: all time-steps.
    std::optional<int> soloTimeStep;
    // The naive raycaster of the benchmark's baseline: every time-step tested at every sample, no
    // skipping of empty space or of gaps between time-steps. Same image, more work.
    bool naive = false;
    // Fully aligned series read four time-steps per fetch from the packed atlas; false sends them
    // through the general path (per time-step fetches), for comparison. Same image.
    bool packAligned = true;
    // The per-sample empty-brick test: by default compiled in where the STF leaves enough bricks
    // empty for it to pay (skipsEmptyBricks); true or false forces it, for comparison. Same image.
    std::optional<bool> emptyBrickTest;
    // A largest-change ray skips the bricks whose change over time cannot beat the one it has kept,
    // where the bricks bound the compositor's change (RaycastVariant::skipUnchangingBricks); false
    // leaves the test out, for comparison. Same image.
    bool skipUnchangingBricks = true;
    // Per-ray arrays of time-step data in the raycaster (RaycastVariant::perRayCaches): by default
    // on a CPU rasterizer and off on a GPU; true or false forces them, for comparison. Same image.
    std::optional<bool> perRayCaches;
    // Lit-sphere styles read their gradients precomputed once per series (gradient_atlas.h), one
    // fetch where they took six: by default from the series' second styled frame on, where the
    // series suits (rectilinear grids) and the memory budget holds the gradient atlas; true from
    // the first such frame, false never (for comparison). The same image but within a voxel of a
    // grid's face or of missing data, to rounding, and along uneven axes to a speckle of pixels.
    std::optional<bool> precomputedGradients;
    // Where the STF's opacity never falls as density rises, temporal-mip with unchanged places ranks
    // the time-steps by density and time alone and looks up the STF of the one it keeps
    // (RaycastVariant::stfOpacityRises); false ranks them by their STF lookups, for comparison.
    // Same image.
    bool rankByDensity = true;
    // Renders only the parts of the rays inside this world box (one process's block of a
    // distributed render, docs/scaling.md); none: whole rays.
    std::optional<Bounds> clipBox;
    // The raycasting pass whole, or one of its first parts alone (RaycastPart), for `bench --stages`.
    RaycastPart raycastPart = RaycastPart::Whole;
    // Times the frame's passes (lastPassTimes): timer queries on a GPU; on a CPU rasterizer with
    // glFinish after each pass, which the frame's own time then includes.
    bool timePasses = false;
};

// Milliseconds of a frame's passes on the device (FrameOptions::timePasses; PassClock).
struct FramePassTimes {
    double entryExitMs = 0.0;  // the proxies' entry and exit depths, every time-step
    double raycastMs = 0.0;    // the raycasting pass (its RaycastPart)
};

// What a renderer holding one block of a series needs to know of the whole: its finest spacing
// (the default step, the opacity reference length and the style footprint; a block can lose the
// finest cells) and its world bounds (where each ray's lattice of samples is anchored).
struct WholeSeries {
    double finestSpacing = 1.0;
    Bounds bounds;
};

class Renderer {
public:
    // Needs a current OpenGL 4.5 context for its whole life.
    explicit Renderer(ShaderLibrary shaders);
    // The raycaster keeps a reference to the shader library: a Renderer stays where it was made.
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // `whole`: where `series` is one block cut from a larger series (distributed rendering), what
    // of the whole its frames follow, so that they take the whole series' samples.
    void setSeries(const Series& series, const std::optional<WholeSeries>& whole = std::nullopt);
    // Uploads the series within `limits` (gpu_memory_budget.h): stored smaller, or coarser, where
    // it must be, drawn with the full series' step length and opacity reference so that the image
    // stays the full series' as far as the resolution allows. Returns what was chosen, with the
    // bytes the driver allocated.
    GpuResidency setSeries(const Series& series, const GpuMemoryLimits& limits,
                           const std::optional<WholeSeries>& whole = std::nullopt);
    bool hasSeries() const { return gpuSeries_.has_value(); }

    // Renders into the internal target (no read-back).
    void draw(const Scene& scene, const View& view, const FrameOptions& options);
    // The last frame's pixels.
    Image readFrame() const { return target_.read(); }
    // The passes' times of the last frame drawn with timePasses (waits for the GPU).
    FramePassTimes lastPassTimes() const;
    // Counters of the last frame drawn with collectStatistics.
    RaycastStatistics lastStatistics() const { return raycaster_.lastStatistics(); }
    // The raycast program of the last frame: the walk, caches, empty-brick test and gradients it
    // took, where FrameOptions leave the choice to the renderer or it falls back (a test that
    // forces a path asserts with it that the path was taken).
    const RaycastVariant& lastVariant() const { return lastVariant_; }
    // Rays of the last frame cut short by the driver (Raycaster::lastCutShortRays).
    std::uint32_t lastCutShortRays() const { return raycaster_.lastCutShortRays(); }
    const RenderTarget& target() const { return target_; }
    // Texture memory of the series (atlases, the gradient atlas included) and of the per-frame buffers.
    std::size_t seriesTextureBytes() const;
    std::size_t frameTextureBytes() const;
    // Of the series' texture memory, the gradient atlas' (0 while there is none).
    std::size_t gradientTextureBytes() const { return gradients_.textureBytes(); }

    // The world-space step a scene asks for: its own, or half the finest voxel spacing.
    double stepLengthFor(const Scene& scene) const;

private:
    // After an upload: the step, the opacity reference, the bounds and the sample lattice of
    // `series`, or of the whole it was cut from.
    void follow(const Series& series, const std::optional<WholeSeries>& whole);
    // The raycasting program a frame needs (builds the gradient atlas where it starts to pay).
    RaycastVariant variantFor(const Scene& scene, const FrameOptions& options);
    // Its uniforms.
    RaycastParameters parametersFor(const Scene& scene, const View& view, const FrameOptions& options,
                                    const RaycastVariant& variant) const;

    ShaderLibrary shaders_;
    std::optional<GpuSeries> gpuSeries_;
    double finestSpacing_ = 1.0;
    Bounds worldBounds_;  // of every time-step: rays outside its projection meet nothing
    Bounds latticeBounds_;  // of the whole series: where each ray's samples are anchored
    bool occupancyStale_ = true;  // a new series needs its brick visibility computed
    bool cpuRasterizer_;          // the context renders on the CPU (llvmpipe): see perRayCaches
    RaycastVariant lastVariant_;
    PrecomputedGradients gradients_;  // the gradient atlas of gpuSeries_ (FrameOptions::precomputedGradients)
    TransferTables transferTables_;
    StyleTextures styleTextures_;
    EntryExitBuffers entryExitBuffers_;
    Raycaster raycaster_;
    RenderTarget target_;
    // Made at the first frame drawn with timePasses: entry/exit and raycasting.
    std::optional<std::array<PassClock, 2>> passClocks_;
};

// Renders one scene headless: loads nothing, just draws and reads back. Convenience for the CLI
// and the tests.
Image renderImage(Renderer& renderer, const Scene& scene, const Bounds& seriesBounds);
// The same where an automatic camera frames `framed` (the visible part) rather than the series.
Image renderImage(Renderer& renderer, const Scene& scene, const Bounds& framed, const Bounds& seriesBounds);

}  // namespace tstyles
