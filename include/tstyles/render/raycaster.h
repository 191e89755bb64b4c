// The multi-volume raycasting pass: overlap extraction, ray iteration, temporal compositor, TSTF
// and final processing in one fragment shader (shaders/raycast.frag), one program per compositor.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <tuple>

#include <glm/glm.hpp>

#include "tstyles/gl/objects.h"
#include "tstyles/gl/program.h"
#include "tstyles/render/packed_aligned_atlas.h"
#include "tstyles/scene/scene.h"

namespace tstyles {

struct RaycastParameters {
    glm::mat4 inverseViewProjection{1.0f};
    glm::ivec2 viewport{0};
    int timeStepCount = 0;
    glm::ivec3 atlasSize{1};
    float stepLength = 0.01f;
    float referenceLength = 0.01f;
    float terminationOpacity = 0.99f;
    glm::vec4 background{0.0f};
    TemporalCompositor compositor = TemporalCompositor::MaxIntensityProjection;
    FinalMode finalMode = FinalMode::Modulate;
    glm::vec2 changeRange{0.0f, 1.0f};
    bool collectStatistics = false;
    // The time-steps that take part, first and last inclusive (the scene's exposure, or a solo step).
    glm::ivec2 exposedSteps{0, std::numeric_limits<int>::max()};
    bool naive = false;     // the benchmark's baseline raycaster
    bool masks = false;     // whether any time-step has a segmentation mask
    bool allAffine = false; // whether every time-step's world -> voxel map is affine
    bool structuredGrids = false;  // the series has structured time-steps (inverse-map lookups compiled in)
    bool unevenAxes = true;        // some time-step has an uneven axis (node lookups compiled in)
    // Fully aligned series: read four time-steps per fetch from the packed atlas (PackedAlignedAtlas).
    bool packedAligned = false;
    // With missing values the packed validities are read too (PackedAlignedAtlas::validity()).
    PackedValidity packedValidity = PackedValidity::None;
    glm::ivec3 sharedValiditySize{1};
    int packedGroupCount = 0;
    glm::ivec3 packedAtlasSize{1};
    // Lit-sphere styles: whether any track is styled, each track's node range, the view rotation
    // and the style-image footprint of a pixel.
    bool styled = false;
    std::array<glm::ivec2, 3> styleTracks{};
    glm::mat3 worldToView{1.0f};
    float styleFootprint = 0.0f;
};

struct RaycastStatistics {
    std::uint64_t rays = 0;     // pixels whose ray meets at least one time-step
    std::uint64_t samples = 0;  // positions where the temporal compositor ran
    std::uint64_t fetches = 0;  // volume texture fetches (density and mask)
};

class Raycaster {
public:
    explicit Raycaster(const ShaderLibrary& shaders);

    // Draws into the currently bound framebuffer, which must hold the premultiplied background:
    // pixels whose ray meets no time-step are discarded. Series, transfer tables and entry/exit
    // buffers must be bound.
    void draw(const RaycastParameters& parameters);
    // Counters of the last draw with collectStatistics (waits for the GPU).
    RaycastStatistics lastStatistics() const;
    // Rays of the last draw that stopped before their exit and below the termination opacity:
    // cut short by the driver's limit on loop passes (llvmpipe), so their pixels are incomplete.
    // Counted in every draw (waits for the GPU).
    std::uint32_t lastCutShortRays() const;

private:
    const Program& programFor(const RaycastParameters& parameters);

    const ShaderLibrary& shaders_;
    // Keyed by compositor, statistics on/off, styled or not, naive or not, masks or not, all
    // affine or not, structured grids or not, packed or not, how packed validity is held, the
    // time-step capacity of the shader's arrays and uneven axes or not.
    std::map<std::tuple<int, bool, bool, bool, bool, bool, bool, bool, PackedValidity, int, bool>, Program>
        programs_;
    VertexArray emptyVertexArray_;
    Buffer statistics_;
};

}  // namespace tstyles
