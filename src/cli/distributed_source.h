// What the processes of `render --distributed` and `animate --distributed` read: where the dataset
// is one manifest, each process reads only its block (block_reading.h), and a scene whose fitting
// needs values (the automatic scene, an "auto" gradient range, a camera framed on the visible
// data) is fitted over the blocks (fitting_over_blocks.h), after which the commands plan their
// frames; otherwise every process reads the whole series and keeps its block, and says why
// (docs/scaling.md, "What each process reads").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "scene_source.h"
#include "tstyles/distributed/distributed_rendering.h"

namespace tstyles::cli {

struct DistributedSource {
    // The scene, and the series' outline (no values) where blocks are read, else the whole series.
    SceneAndSeries opened;
    std::optional<std::filesystem::path> blockManifest;  // set: each process reads only its block
    std::string wholeReason;                              // otherwise: why not
    // The automatic scene with blocks read: its STF opacity is still to come from the blocks.
    bool automaticOpacity = false;
};

// As openSceneOrDataset, but with the outline only where blocks can be read.
DistributedSource openDistributedSource(const std::vector<std::filesystem::path>& inputs,
                                        const std::vector<std::filesystem::path>& datasetFiles,
                                        const DatasetOptions& datasetOptions);

// Collective: the distributed rendering of `fitted` (fitted to `source`'s series), each process's
// block read by itself or cut from the whole series.
DistributedRendering startDistributedRendering(const MpiSession& mpi, Renderer& renderer, SceneOnSeries fitted,
                                               const DistributedSource& source, const DatasetOptions& datasetOptions,
                                               const DistributedRendering::BlockUpload& upload);

// For the summary line: "each process read only its block", or "every process read the whole
// series: REASON"; and, where `series` has structured time-steps, that every process keeps those
// whole (a world block does not cut them; series_crop.h).
std::string readingText(const DistributedSource& source, const Series& series);

}  // namespace tstyles::cli
