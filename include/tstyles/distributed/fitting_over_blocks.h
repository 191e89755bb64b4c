// Fitting the parts of a scene that the series' values decide, where each process holds only its
// block (docs/scaling.md, "What each process reads"): the automatic scene's STF opacity (from the
// density histogram), a gradient TSTF range of "auto" (from the visible places' changes over
// time) and a camera that frames the visible data (their bounds). Each process takes its share of
// each statistic, MPI combines the shares, and every process gets what one process holding the
// whole series gets: the same histogram, the same visible node boxes, the same changes.
#pragma once

#include "tstyles/distributed/block_decomposition.h"
#include "tstyles/distributed/block_reading.h"
#include "tstyles/distributed/mpi_session.h"
#include "tstyles/scene/scene.h"

namespace tstyles {

struct SceneFittedOverBlocks {
    Scene scene;
    Bounds framed;  // what an automatic camera frames: the visible data, or the whole series
};

// Whether fitting `scene` reads values: the automatic scene's opacity, an "auto" gradient TSTF
// range, or a camera framed on the visible data.
bool fittingReadsValues(const Scene& scene, bool automaticOpacity);

// Collective. `scene` fitted to `displayOutline` (the series' outline in the scene's display
// frame), with the parts that need values fitted over every process's `block` of `blocks`; where
// `automaticOpacity`, the scene is the automatic one and its STF opacity comes from the histogram
// (automaticOpacityWindow). `framedOutline`: what the camera frames where no values decide it.
SceneFittedOverBlocks fitOverBlocks(const MpiSession& mpi, const BlockDecomposition& blocks, Scene scene,
                                    bool automaticOpacity, const Series& displayOutline, const BlockOfSeries& block,
                                    const Bounds& framedOutline);

// Collective. Each time-step's raw value range (TimeStep::rawRange) of `block` made the whole
// time-step's: the range over every process's block, since a block read only its rows where the
// manifest gives the value range (loadSeries). NaN, NaN where no block has a value with data.
void combineRawRanges(const MpiSession& mpi, Series& block);

}  // namespace tstyles
