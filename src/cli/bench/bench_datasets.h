// The datasets of `tstyles bench` (one line per dataset), the compositors it measures, and its median. A dataset whose folder is not under data/
// (it arrives with another feature, or was not generated) is skipped with a printed note.
#pragma once

#include <string>
#include <vector>

#include "tstyles/scene/scene.h"

namespace tstyles::cli {

struct BenchDataset {
    std::string folder;       // under the bundled data directory
    std::string description;  // what the line of the table measures
    // The scenes that supply camera and transfer functions: <scenePrefix>[styled-]<compositor>.json
    // in data/scenes.
    std::string scenePrefix;
    // A dataset with scenes of its own (already styled, used with and without --styled) names them
    // here instead: one for temporal MIP and average (index TSTF), one for max density change.
    std::string indexScene;
    std::string changeScene;
};

// The benchmark matrix's datasets, in the order of the table.
const std::vector<BenchDataset>& benchDatasets();

// The entry for a folder; folders not in the table get the super-ellipsoid's Figure 4 scenes.
BenchDataset benchDatasetFor(const std::string& folder);

// The compositors every dataset is measured with.
inline constexpr TemporalCompositor kBenchCompositors[] = {
    compositorNamed("temporal-mip"), compositorNamed("temporal-average"), compositorNamed("temporal-max-change")};

// The median of frame times (the mean of the middle two for an even count); `values` not empty.
double median(std::vector<double> values);

// The bundled scene for a dataset and compositor, flat or with lit-sphere styles.
std::string benchSceneFor(const BenchDataset& dataset, TemporalCompositor compositor, bool styled);

}  // namespace tstyles::cli
