// The compile-time switches of the raycasting program. RaycastVariant::defines()
// (src/render/raycast_variant.cpp) defines every one of them, and is the one place of their
// defaults; a program built without one stops here instead of taking a default silently.
//   STYLED              1 when a transfer function of the scene uses a lit-sphere style
//   STYLED_TRACKS       bit t set when track t (STF_TRACK, INDEX_TSTF_TRACK, GRADIENT_TSTF_TRACK) has styles
//   SINGLE_NODE_STYLE_TRACKS bit t set when styled track t has one colour node: one style lookup at
//                       every value, where several nodes blend the lookups of the two around it
//   STF_OPACITY_RISES   1 when the STF's opacity never falls as density rises: temporal-mip with
//                       UNCHANGED_TIME ranks the time-steps by density alone (the same order as by
//                       STF opacity, then density) and classifies only the one it keeps
//   HAS_MASKS           1 when a time-step has a segmentation mask (the atlas' last channel)
//   MISSING_VALUES      1 when the density atlas holds (density * validity, validity) pairs
//   ALL_AFFINE          1 when every time-step's world -> voxel map is affine (even rectilinear grids)
//   STRUCTURED_GRIDS    1 when the series has explicit structured time-steps
//   RECTILINEAR_GRIDS   1 when a time-step is a rectilinear grid (even or uneven axes)
//   UNEVEN_AXES         1 when a time-step has an uneven rectilinear axis
//   UNEVEN_AXIS_WALK    1 when an uneven axis' bucket may hold several nodes (UnevenAxisTable::crowdedBuckets)
//   BEAM_GRIDS          1 when a time-step is a beam (sonar) grid
//   EVEN_BEAMS          1 when every beam grid's beams are evenly spaced on both axes
//   PACKED_ALIGNED      1 when the packed groups of four are walked (walk_packed_groups.glsl)
//   PACKED_VALIDITY     a PACKED_VALIDITY_* code of contract.glsl
//   PACKED_GROUP_MASKS  1 when each brick's mask names the packed groups visible in it (at most 32 groups)
//   MAX_TIME_STEPS      capacity of the per-ray arrays of time-steps
//   COLLECT_STATISTICS  1 to count rays, samples and fetches
//   SKIP_EMPTY_BRICKS   1 to test at each sample whether every time-step there is in an empty brick
//   SKIP_UNCHANGING_BRICKS 1 when the ray mode reads the change (largest-change) and the packed walk's
//                       bricks bound it: a ray skips the bricks whose change cannot beat the one it keeps
//   CUSTOM_READS_INDEX  the scene's own compositor (tc_custom.glsl) returns a time-step index
//   PER_RAY_CACHES      1 for per-ray arrays of time-step data (voxel rays, the average's deferred
//                       styling): they pay on a CPU rasterizer and cost on a GPU (Renderer decides)
//   PRECOMPUTED_GRADIENTS 1 when styles read gradients from the gradient atlas (one fetch, computed
//                       once per series by gradient_atlas.comp) instead of six density fetches
//   UNCHANGED_TIME      1 when a compositor that picks a time-step leaves places whose densities do
//                       not change over time (or tie) without time colour (CompositorOptions::unchanged)
//   RAYCAST_PART        a RAYCAST_PART_* code of contract.glsl: the whole pass, or only its ray setup or
//                       its march, which `bench --stages` times (RaycastVariant::part)
// Each is a switch and not a run-time test because llvmpipe runs both sides of a branch that the 8
// pixels it shades together disagree on, masked, and inside the ray's loop even one that none of them
// takes (docs/performance.md, "llvmpipe and branches").
#if !defined(STYLED) || !defined(HAS_MASKS) || !defined(ALL_AFFINE) || !defined(STRUCTURED_GRIDS) || \
    !defined(UNEVEN_AXES) || !defined(BEAM_GRIDS) || !defined(EVEN_BEAMS) || !defined(PACKED_ALIGNED) ||   \
    !defined(PACKED_VALIDITY) || !defined(MAX_TIME_STEPS) || !defined(COLLECT_STATISTICS) ||             \
    !defined(CUSTOM_READS_INDEX) || !defined(STYLED_TRACKS) || !defined(SKIP_EMPTY_BRICKS) || \
    !defined(MISSING_VALUES) || !defined(UNEVEN_AXIS_WALK) || !defined(PER_RAY_CACHES) ||              \
    !defined(PRECOMPUTED_GRADIENTS) || !defined(RECTILINEAR_GRIDS) || !defined(PACKED_GROUP_MASKS) ||  \
    !defined(UNCHANGED_TIME) || !defined(RAYCAST_PART) || !defined(SKIP_UNCHANGING_BRICKS) ||          \
    !defined(SINGLE_NODE_STYLE_TRACKS) || !defined(STF_OPACITY_RISES)
#error "a raycasting switch is not defined: build the program through RaycastVariant"
#endif
#if !RECTILINEAR_GRIDS && !STRUCTURED_GRIDS && !BEAM_GRIDS
#error "a series holds at least one kind of grid"
#endif
#if SKIP_UNCHANGING_BRICKS && !PACKED_ALIGNED
#error "only the packed walk's bricks bound the change over time"
#endif

// A series of one kind of grid needs no test of a time-step's kind: isBeamGrid and isStructured
// are then constant, and the paths of the kinds it lacks leave the program (inside the ray's loop
// llvmpipe would run them, masked, at every sample: the sonar's frames took a third longer with
// the rectilinear path beside the beam one).
const bool ONLY_BEAM_GRIDS = BEAM_GRIDS != 0 && RECTILINEAR_GRIDS == 0 && STRUCTURED_GRIDS == 0;
const bool ONLY_STRUCTURED_GRIDS = STRUCTURED_GRIDS != 0 && RECTILINEAR_GRIDS == 0 && BEAM_GRIDS == 0;
#if PRECOMPUTED_GRADIENTS && (STRUCTURED_GRIDS || BEAM_GRIDS)
#error "precomputed gradients are for rectilinear grids"
#endif
