// Which raycasting program a frame needs: its temporal compositor module, its walk over the
// time-steps, its ray mode module and its compile-time switches. The one place where those choices become #defines and
// modules, where each switch has its default, and the program cache's key.
#pragma once

#include <compare>
#include <vector>

#include "tstyles/gl/program.h"
#include "tstyles/render/packed_aligned_atlas.h"
#include "tstyles/scene/scene.h"

namespace tstyles {

// How the time-steps at a sample are found and read.
enum class TimeStepWalk {
    RayList,       // the ray's list of the time-steps it meets, with empty-space skipping
    PackedGroups,  // fully aligned series: four time-steps per fetch from the packed atlas
    Naive,         // the benchmark's baseline: every time-step at every sample, nothing skipped
};

const char* walkName(TimeStepWalk walk);  // "ray list", "packed groups", "naive"

// How much of the raycasting pass the program runs: all of it for pictures; one of its first parts
// alone for `bench --stages`, which times each to see where a frame's time goes.
enum class RaycastPart {
    Whole,
    RaySetup,  // each ray's overlap extraction and the walk's list, then the pixel ends
    March,     // the samples' lattice, the walk and the empty-space test; nothing fetched or composited
};


struct RaycastVariant {
    TemporalCompositor compositor = compositorNamed("temporal-mip");
    RayMode rayMode = kCompositeRay;
    // kCustomCompositor: the scene's code, its name in compiler messages, what reads it.
    std::string customCode;
    std::string customCodeName;
    CompositorReads customReads = CompositorReads::IndexTstf;
    TimeStepWalk walk = TimeStepWalk::RayList;
    // Bit t set: transfer-function track t (STF, index TSTF, gradient TSTF) uses lit-sphere styles.
    int styledTracks = 0;
    // Bit t set: styled track t has one colour node, so its colour at every value is one lookup of
    // that node's style, where a track of several nodes blends the lookups of the two around it.
    int singleNodeStyleTracks = 0;
    // The STF's opacity never falls as density rises (TransferTables::stfOpacityRises): a picking
    // compositor that ranks time-steps by STF opacity, then density, then time (temporal-mip with
    // unchanged places) ranks them by density and time alone, the same order, and classifies only
    // the time-step it keeps.
    bool stfOpacityRises = false;
    bool masks = false;            // a time-step has a segmentation mask
    bool missingValues = false;    // the density atlas holds (density * validity, validity) pairs
    bool allAffine = false;        // every time-step's world -> voxel map is affine
    bool structuredGrids = false;  // the series has structured time-steps (inverse-map lookups)
    bool rectilinearGrids = true;  // a time-step is a rectilinear grid (even or uneven axes)
    bool unevenAxes = false;       // a time-step has an uneven axis (node lookups)
    bool unevenAxisWalk = false;   // an uneven axis' bucket may hold several nodes (walking lookups)
    bool beamGrids = false;        // a time-step is a beam (sonar) grid
    bool evenBeams = false;        // every beam grid has evenly spaced beams on both axes
    // PackedGroups with missing values: how the packed validities are held.
    PackedValidity packedValidity = PackedValidity::None;
    // PackedGroups: each brick's mask names the groups visible in it (PackedAlignedAtlas::hasGroupMasks),
    // and compositors that leave transparent time-steps out read only those groups.
    bool packedGroupMasks = false;
    // Capacity of the shader's per-ray arrays of time-steps (timeStepCapacityFor).
    int timeStepCapacity = 8;
    bool collectStatistics = false;
    // Test at each sample whether every time-step there is in an empty brick (emptySpaceUntil):
    // worth its cost only where the STF leaves some bricks empty (skipsEmptyBricks).
    bool skipEmptyBricks = true;
    // A largest-change ray skips the bricks whose change over time cannot beat the change it has
    // kept (packed walk only; Renderer decides where the bricks bound the compositor's change).
    bool skipUnchangingBricks = false;
    // Per-ray arrays of the time-steps' voxel rays and the temporal average's deferred styling:
    // they pay on a CPU rasterizer, and cost on a GPU, where arrays indexed at run time live in slow
    // per-thread memory (Renderer picks by the driver).
    bool perRayCaches = true;
    // Styles read gradients from the gradient atlas (render/gradient_atlas.h), one fetch where six
    // were: for rectilinear series (Renderer decides).
    bool precomputedGradients = false;
    // The compositor leaves unchanged places without time colour (CompositorOptions::unchanged;
    // compositors whose table line takesUnchanged).
    bool unchangedTime = false;
    RaycastPart part = RaycastPart::Whole;

    auto operator<=>(const RaycastVariant&) const = default;

    bool styled() const { return styledTracks != 0; }

    // Every switch of shaders/variant_switches.glsl.
    ShaderDefines defines() const;
    // What "compositor.glsl", "time_step_walk.glsl" and "ray_mode.glsl" stand for.
    ShaderModules modules() const;
    // "temporal-average, ray list, styled, masks, ..." for messages.
    std::string describe() const;
};

// The per-ray array capacity for a series of `timeStepCount` time-steps: a power of two from 8 up,
// so that a few more or fewer time-steps reuse the same program.
int timeStepCapacityFor(int timeStepCount);

// Whether the empty-brick test pays for a series whose bricks are this share empty under the
// STF: below kMinEmptyBrickShare it can skip little, and costs a voxel mapping and an occupancy
// fetch per sample (23 % of a sonar frame, where no brick is empty; docs/performance.md).
inline constexpr double kMinEmptyBrickShare = 0.05;
bool skipsEmptyBricks(double emptyBrickShare);

// The program that runs `part` of `whole`'s pass: the same walk, grids and switches, and one
// compositor without styles for all (the parts end before a compositor runs).
RaycastVariant partOf(const RaycastVariant& whole, RaycastPart part);

// Every variant a frame can ask for, up to the array capacity (which changes array sizes only):
// every compositor x walk x grid kind x styled, with masks and statistics on and off (the custom
// compositor with an example body that reads each input, for both of its readers), and the parts
// of each (partOf); every other ray mode with every compositor it takes (on each walk, styled and
// not), and on every walk x grid kind (with masks, missing values and the group masks on and off).
// The build validates each of them (tools/validate_raycast_variants.cpp).
std::vector<RaycastVariant> requestableRaycastVariants();

}  // namespace tstyles
