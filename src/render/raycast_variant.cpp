// Raycasting program variants: their #defines, their modules and the list the build validates.
#include "tstyles/render/raycast_variant.h"

#include <algorithm>
#include <set>
#include <string>

#include "tstyles/render/shader_contract.h"
#include "tstyles/scene/ray_modes.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

// A custom compositor's body for the build's validation: it reads every input.
constexpr const char* kExampleCustomBody = R"(
    float best = -1.0;
    int peak = -1;
    for (int i = 0; i < count; ++i) {
        if (hasData[i] && inMask[i] && stf[i].a > 0.0 && density[i] + 0.0 * time[i] > best) {
            best = density[i];
            peak = i;
        }
    }
    return float(peak);
)";

const char* walkModule(TimeStepWalk walk) {
    switch (walk) {
        case TimeStepWalk::RayList: return "walk_ray_list.glsl";
        case TimeStepWalk::PackedGroups: return "walk_packed_groups.glsl";
        case TimeStepWalk::Naive: return "walk_naive.glsl";
    }
    return "walk_ray_list.glsl";
}

int packedValidityCode(PackedValidity validity) {
    switch (validity) {
        case PackedValidity::None: return contract::PACKED_VALIDITY_NONE;
        case PackedValidity::PerGroup: return contract::PACKED_VALIDITY_PER_GROUP;
        case PackedValidity::Shared: return contract::PACKED_VALIDITY_SHARED;
    }
    return contract::PACKED_VALIDITY_NONE;
}

int raycastPartCode(RaycastPart part) {
    switch (part) {
        case RaycastPart::Whole: return contract::RAYCAST_PART_WHOLE;
        case RaycastPart::RaySetup: return contract::RAYCAST_PART_RAY_SETUP;
        case RaycastPart::March: return contract::RAYCAST_PART_MARCH;
    }
    return contract::RAYCAST_PART_WHOLE;
}

const char* flag(bool value) { return value ? "1" : "0"; }

// Every transfer-function track styled: the program with the most style code (a subset leaves some
// of it out).
constexpr int kAllStyleTracks = 0b111;

// The kinds of grid a series can hold, as the switches that the renderer derives from it.
struct GridKind {
    bool allAffine;
    bool unevenAxes;
    bool structuredGrids;
    bool beamGrids;
    bool evenBeams;
    bool rectilinearGrids;  // a time-step is rectilinear
    bool onlyRectilinear;   // only rectilinear series can be packed
};

constexpr GridKind kGridKinds[] = {
    {true, false, false, false, false, true, true},     // even rectilinear
    {false, true, false, false, false, true, true},     // uneven rectilinear
    {false, false, false, true, true, false, false},    // beam grids alone, evenly spaced beams
    {false, false, false, true, false, false, false},   // beam grids alone, uneven beams
    {false, false, true, false, false, false, false},   // structured grids alone
    {false, true, true, true, false, true, false},      // structured, uneven rectilinear and beam grids together
};

// The custom compositor twice, once for each transfer function that may read it.
std::vector<RaycastVariant> compositorChoices() {
    std::vector<RaycastVariant> choices;
    for (std::size_t line = 0; line < temporalCompositors().size(); ++line) {
        RaycastVariant variant;
        variant.compositor = TemporalCompositor(line);
        if (variant.compositor != kCustomCompositor) {
            choices.push_back(variant);
            continue;
        }
        variant.customCode = kExampleCustomBody;
        variant.customCodeName = "example custom compositor";
        for (CompositorReads reads : {CompositorReads::IndexTstf, CompositorReads::GradientTstf}) {
            variant.customReads = reads;
            choices.push_back(variant);
        }
    }
    return choices;
}

}  // namespace

const char* walkName(TimeStepWalk walk) {
    switch (walk) {
        case TimeStepWalk::RayList: return "ray list";
        case TimeStepWalk::PackedGroups: return "packed groups";
        case TimeStepWalk::Naive: return "naive";
    }
    return "ray list";
}

RaycastVariant partOf(const RaycastVariant& whole, RaycastPart part) {
    RaycastVariant variant = whole;
    variant.part = part;
    if (part == RaycastPart::Whole) return variant;
    variant.compositor = compositorNamed("temporal-mip");
    variant.rayMode = kCompositeRay;
    variant.customCode.clear();
    variant.customCodeName.clear();
    variant.customReads = CompositorReads::IndexTstf;
    variant.styledTracks = 0;
    variant.singleNodeStyleTracks = 0;
    variant.stfOpacityRises = false;
    variant.precomputedGradients = false;
    variant.unchangedTime = false;
    variant.skipUnchangingBricks = false;
    return variant;
}

ShaderDefines RaycastVariant::defines() const {
    return {
        {"STYLED", flag(styled())},
        {"STYLED_TRACKS", std::to_string(styledTracks)},
        {"SINGLE_NODE_STYLE_TRACKS", std::to_string(singleNodeStyleTracks)},
        {"STF_OPACITY_RISES", flag(stfOpacityRises)},
        {"HAS_MASKS", flag(masks)},
        {"MISSING_VALUES", flag(missingValues)},
        {"ALL_AFFINE", flag(allAffine)},
        {"STRUCTURED_GRIDS", flag(structuredGrids)},
        {"RECTILINEAR_GRIDS", flag(rectilinearGrids)},
        {"UNEVEN_AXES", flag(unevenAxes)},
        {"UNEVEN_AXIS_WALK", flag(unevenAxisWalk)},
        {"BEAM_GRIDS", flag(beamGrids)},
        {"EVEN_BEAMS", flag(evenBeams)},
        {"PACKED_ALIGNED", flag(walk == TimeStepWalk::PackedGroups)},
        {"PACKED_VALIDITY", std::to_string(packedValidityCode(packedValidity))},
        {"PACKED_GROUP_MASKS", flag(packedGroupMasks)},
        {"MAX_TIME_STEPS", std::to_string(timeStepCapacity)},
        {"COLLECT_STATISTICS", flag(collectStatistics)},
        {"SKIP_EMPTY_BRICKS", flag(skipEmptyBricks)},
        {"SKIP_UNCHANGING_BRICKS", flag(skipUnchangingBricks)},
        {"CUSTOM_READS_INDEX", flag(customReads == CompositorReads::IndexTstf)},
        {"PER_RAY_CACHES", flag(perRayCaches)},
        {"PRECOMPUTED_GRADIENTS", flag(precomputedGradients)},
        {"UNCHANGED_TIME", flag(unchangedTime)},
        {"RAYCAST_PART", std::to_string(raycastPartCode(part))},
    };
}

ShaderModules RaycastVariant::modules() const {
    ShaderModules modules{{"time_step_walk.glsl", walkModule(walk), std::nullopt},
                          {"ray_mode.glsl", rayModeInfo(rayMode).shaderModule, std::nullopt}};
    if (compositor == kCustomCompositor) {
        modules.push_back({"compositor.glsl", "tc_custom.glsl", std::nullopt});
        modules.push_back({"custom_compositor_body.glsl", customCodeName, customCode});
    } else {
        modules.push_back({"compositor.glsl", compositorInfo(compositor).shaderModule, std::nullopt});
    }
    return modules;
}

std::string RaycastVariant::describe() const {
    std::string text = toString(compositor) + ", " + toString(rayMode) + ", " + walkName(walk);
    for (const auto& [name, value] : defines()) text += ", " + name + "=" + value;
    return text;
}

bool skipsEmptyBricks(double emptyBrickShare) { return emptyBrickShare >= kMinEmptyBrickShare; }

int timeStepCapacityFor(int timeStepCount) {
    int capacity = 8;
    while (capacity < timeStepCount) capacity *= 2;
    return capacity;
}

std::vector<RaycastVariant> requestableRaycastVariants() {
    std::vector<RaycastVariant> variants;
    for (const RaycastVariant& choice : compositorChoices()) {
        for (TimeStepWalk walk : {TimeStepWalk::RayList, TimeStepWalk::PackedGroups, TimeStepWalk::Naive}) {
            for (const GridKind& kind : kGridKinds) {
                if (walk == TimeStepWalk::PackedGroups && !kind.onlyRectilinear) continue;
                for (bool styled : {false, true}) {
                    RaycastVariant variant = choice;
                    variant.walk = walk;
                    variant.styledTracks = styled ? kAllStyleTracks : 0;
                    variant.allAffine = kind.allAffine;
                    variant.unevenAxes = kind.unevenAxes;
                    variant.unevenAxisWalk = kind.unevenAxes && !styled;  // both lookups compile
                    variant.structuredGrids = kind.structuredGrids;
                    variant.rectilinearGrids = kind.rectilinearGrids;
                    variant.beamGrids = kind.beamGrids;
                    variant.evenBeams = kind.evenBeams;
                    // Statistics and the empty-brick test on in half of the set each, so that
                    // both sides of those switches compile.
                    variant.collectStatistics = !styled;
                    variant.skipEmptyBricks = styled;
                    variant.perRayCaches = !styled;
                    // Both sides of the unchanged-time switch compile, in half of the set each.
                    variant.unchangedTime = styled && compositorInfo(choice.compositor).takesUnchanged;
                    if (walk == TimeStepWalk::PackedGroups) {
                        // Packed series have no masks; their validities come in three kinds.
                        for (PackedValidity validity :
                             {PackedValidity::None, PackedValidity::PerGroup, PackedValidity::Shared}) {
                            variant.packedValidity = validity;
                            variant.missingValues = validity != PackedValidity::None;
                            // Both sides of the group-mask switch compile, in part of the set each.
                            variant.packedGroupMasks = validity != PackedValidity::PerGroup;
                            variants.push_back(variant);
                        }
                        variant.packedValidity = PackedValidity::None;
                        variant.packedGroupMasks = false;
                    } else {
                        for (bool masks : {false, true}) {
                            variant.masks = masks;
                            // Both sides of the missing-value switch compile, in half of the set each.
                            variant.missingValues = masks;
                            variants.push_back(variant);
                        }
                    }
                    // Precomputed gradients: styled rectilinear series (even or uneven axes), with
                    // missing values and without (the packed walk's shared validity for them).
                    // With them, single-node style tracks and the ranking by density where the
                    // STF's opacity rises: both sides of those switches compile.
                    if (styled && kind.onlyRectilinear) {
                        variant.precomputedGradients = true;
                        variant.singleNodeStyleTracks = kAllStyleTracks;
                        variant.stfOpacityRises = variant.unchangedTime;
                        for (bool missing : {false, true}) {
                            variant.missingValues = missing;
                            if (walk == TimeStepWalk::PackedGroups) {
                                variant.packedValidity = missing ? PackedValidity::Shared : PackedValidity::None;
                                variant.packedGroupMasks = true;
                            }
                            variants.push_back(variant);
                        }
                    }
                }
            }
        }
    }
    // The other ray modes: each with every compositor it takes, on each walk, styled and not (on even
    // rectilinear grids); and with temporal-mip (and the average, which composites) on every walk x
    // grid kind, masks and missing values on and off (the composite lines above cover the rest of the
    // switches, which the modes do not touch).
    const std::size_t compositeVariants = variants.size();
    for (std::size_t line = 0; line < rayModes().size(); ++line) {
        const RayMode mode(line);
        if (mode == kCompositeRay) continue;
        for (std::size_t i = 0; i < compositeVariants; ++i) {
            RaycastVariant variant = variants[i];
            const CompositorReads reads = variant.compositor == kCustomCompositor
                                              ? variant.customReads
                                              : compositorInfo(variant.compositor).reads;
            if (rayModeInfo(mode).needsValue && reads == CompositorReads::Composited) continue;
            // A mode that reads the change: the picking compositors measure it with the unchanged-time
            // switch on (as the renderer builds them); the scene's own index compositor does not.
            if (rayModeInfo(mode).readsChange && reads == CompositorReads::IndexTstf) {
                if (!compositorInfo(variant.compositor).takesUnchanged) continue;
                variant.unchangedTime = true;
            }
            // And skips the bricks that change too little, on the packed walk where the validities
            // let the bricks bound the change (both sides compile: the styled half skips).
            variant.skipUnchangingBricks = rayModeInfo(mode).readsChange && variant.walk == TimeStepWalk::PackedGroups &&
                                           variant.packedValidity != PackedValidity::PerGroup && variant.styled();
            const bool everyCompositor = variant.allAffine && !variant.masks && !variant.precomputedGradients &&
                                         variant.packedValidity != PackedValidity::Shared;
            const bool everyGrid = variant.compositor == compositorNamed("temporal-mip") ||
                                   (variant.compositor == compositorNamed("temporal-average") && !rayModeInfo(mode).needsValue);
            if (!everyCompositor && !everyGrid) continue;
            variant.rayMode = mode;
            if (std::find(variants.begin() + std::ptrdiff_t(compositeVariants), variants.end(), variant) == variants.end())
                variants.push_back(variant);
        }
    }
    // The parts `bench --stages` times, once each: they leave the compositor and styles out.
    std::set<RaycastVariant> parts;
    for (const RaycastVariant& whole : variants)
        for (RaycastPart part : {RaycastPart::RaySetup, RaycastPart::March}) parts.insert(partOf(whole, part));
    variants.insert(variants.end(), parts.begin(), parts.end());
    return variants;
}

}  // namespace tstyles
