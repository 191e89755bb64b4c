// Sort-last rendering of one fitted scene over MPI processes (docs/scaling.md): the series' world
// is split into one block per process (BlockDecomposition); each process keeps only its block of
// every time-step (with ghost nodes, so filtering and gradients are seamless), renders its block
// with the ordinary raycaster, rays clipped to the block, and the frames are composited in
// visibility order onto process 0 (radix-k), which adds the background and the annotations.
// A temporal compositor needs every time-step at a sample; each process has all of them for its
// block, so splitting space is exact where splitting time would not be.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>

#include "tstyles/distributed/block_decomposition.h"
#include "tstyles/distributed/block_reading.h"
#include "tstyles/distributed/mpi_session.h"
#include "tstyles/render/annotated_rendering.h"
#include "tstyles/render/renderer.h"
#include "tstyles/scene/automatic_scene.h"

namespace tstyles {

// Ghost nodes kept around each block: trilinear filtering reads the cell's far nodes and the
// central-difference gradient one node further.
inline constexpr int kBlockGhostNodes = 2;

// Per process, what the last frame took (milliseconds).
struct DistributedFrameTimes {
    double render = 0.0;     // raycasting the block and reading it back
    double composite = 0.0;  // radix-k and the gather onto process 0
};

class DistributedRendering {
public:
    // Uploads a process's block into the renderer (Renderer::setSeries with `whole`, within the
    // front end's GPU memory budget).
    using BlockUpload = std::function<void(const Series& block, const WholeSeries& whole)>;

    // Collective. Keeps this process's block of `fitted`'s series and has `upload` put it into
    // `renderer` (which needs a current context); process 0 also keeps the series' outline for
    // annotations.
    DistributedRendering(const MpiSession& mpi, Renderer& renderer, SceneOnSeries fitted, const BlockUpload& upload);

    // Reads this process's block of the series: every time-step cut to `box` (world coordinates of
    // the scene's display frame) with kBlockGhostNodes around it, values mapped to density by the
    // whole series' value range.
    using BlockReader = std::function<BlockOfSeries(const Bounds& box)>;

    // Collective. The same, where `fittedOutline`'s series has no values (the outline of the
    // series in the scene's display frame, the scene fitted to it) and each process reads only
    // its own block with `read`: no process holds more than its block and what `read` needs.
    // The parts of the scene that the values decide (an "auto" gradient range, a camera framed on
    // the visible data, and where `automaticOpacity` the automatic scene's STF opacity) are then
    // fitted over the blocks (fitting_over_blocks.h), as one process fits them to the whole series.
    DistributedRendering(const MpiSession& mpi, Renderer& renderer, SceneOnSeries fittedOutline, const BlockReader& read,
                         const BlockUpload& upload, bool automaticOpacity = false);

    // Collective: the scene's frame, annotated, on process 0; an empty image on the others.
    // `options`: as for Renderer::draw, but for the size and clip box, which the blocks set.
    Image render(const Scene& scene, FrameOptions options = {});

    const Scene& scene() const { return scene_; }
    // What the camera frames where the scene leaves it to the data (Framing).
    const Bounds& framed() const { return framed_; }
    const Bounds& block() const { return blocks_.block(mpi_.rank()); }
    std::size_t processCount() const { return std::size_t(mpi_.processCount()); }
    // Voxels of this process's block over all time-steps, ghosts included.
    std::size_t blockVoxelCount() const { return blockVoxels_; }
    const DistributedFrameTimes& lastTimes() const { return lastTimes_; }

private:
    // What both public constructors start from: the blocks of the whole series' bounds.
    DistributedRendering(const MpiSession& mpi, Renderer& renderer, Scene scene, const Bounds& wholeBounds,
                         const Bounds& framed, const DisplayFrame& frame);
    // Keeps `block` (this process's) and uploads it; process 0 keeps `outline` for annotations.
    void keepBlock(const Series& block, Series outline, const BlockUpload& upload);

    const MpiSession& mpi_;
    Renderer& renderer_;
    Scene scene_;
    BlockDecomposition blocks_;
    Bounds wholeBounds_;
    Bounds framed_;
    DisplayFrame frame_;
    Series outline_;  // the series without values: times, grids, metadata (process 0)
    std::optional<SceneAnnotator> annotator_;
    std::size_t blockVoxels_ = 0;
    DistributedFrameTimes lastTimes_;
};

}  // namespace tstyles
