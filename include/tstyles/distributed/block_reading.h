// Reading one process's block of a manifest series without ever holding the whole series: of each
// time-step only the block's values are kept as its file is read through, and its grid is taken
// into the scene's display frame and cut alike, so a process holds its block of every time-step
// and never a whole time-step (docs/scaling.md, "What each process reads").
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "tstyles/data/display_frame.h"
#include "tstyles/data/node_block.h"
#include "tstyles/data/read_options.h"
#include "tstyles/data/series.h"

namespace tstyles {

// One process's block of a series, and where its nodes lie in the whole series' grids.
struct BlockOfSeries {
    Series series;  // in the display frame, every time-step cut to the block
    // Per time-step, which of the file grid's nodes it holds (the display frame keeps a grid's nodes
    // and their order); nullopt for a time-step kept whole (structured grids).
    std::vector<std::optional<NodeBlock>> nodes;
};

// The block of the manifest's series that the world box `box` (display coordinates) needs, with
// kBlockGhostNodes around it, as cropSeriesToBox cuts it from the whole series in the display
// frame: the same grids, values, masks and value range (the range comes from whole time-steps, so
// every process finds the same). `displayOutline`: the series' outline in the display frame
// (loadSeriesOutline, then applyDisplayFrame), from which the block's size is known before any
// value is read, and which gives the block its display axes. `options`:
// --max-memory and --precision (a manifest takes no other reading option); the memory check counts
// the block's voxels.
BlockOfSeries readManifestBlock(const std::filesystem::path& manifest, const ReadOptions& options,
                         const Series& displayOutline, const DisplayFrame& frame, const Bounds& box);

}  // namespace tstyles
