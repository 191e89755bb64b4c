// The multi-volume raycasting pass: overlap extraction, ray iteration, temporal compositor, TSTF
// and final processing in one fragment shader (shaders/raycast.frag), one program per RaycastVariant.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/gl/objects.h"
#include "tstyles/gl/program.h"
#include "tstyles/render/raycast_variant.h"
#include "tstyles/render/shader_contract.h"
#include "tstyles/scene/scene.h"

namespace tstyles {

// A compositor's or a ray mode's option's uniform (CompositorOption::uniform, RayModeOption::uniform,
// declared by the module) and its value, of the GLSL type of the option's kind.
struct ModuleOptionUniform {
    const char* name;
    std::variant<float, int, glm::ivec2, glm::vec4> value;
};

// The uniforms of a raycasting pass; which program it needs is its RaycastVariant.
struct RaycastParameters {
    glm::mat4 inverseViewProjection{1.0f};
    glm::ivec2 viewport{0};
    int timeStepCount = 0;
    glm::ivec3 atlasSize{1};
    float stepLength = 0.01f;
    float referenceLength = 0.01f;
    float terminationOpacity = 0.99f;
    glm::vec4 background{0.0f};
    FinalMode finalMode = FinalMode::Modulate;
    glm::vec2 changeRange{0.0f, 1.0f};
    // The options of the variant's compositor (those its table line takes), by their uniforms.
    std::vector<ModuleOptionUniform> compositorOptions;
    // The options of the variant's ray mode, by their uniforms.
    std::vector<ModuleOptionUniform> rayOptions;
    // visibleDensityRange of the STF's table: time-steps outside it are transparent.
    glm::vec2 stfVisibleRange{0.0f, 1.0f};
    // CompositorOptions::unchanged (RaycastVariant::unchangedTime): the change up to which a place
    // is unchanged, the difference up to which two time-steps tie, and the share of the STF's
    // opacity an unchanged place keeps; a changing place's opacity as if `changedGain` times as thick.
    std::array<float, contract::UNCHANGED_DENSITY_BANDS> unchangedBelow{};  // per density band
    std::array<float, contract::UNCHANGED_DENSITY_BANDS> unchangedTie{};
    float changedGain = 1.0f;
    float unchangedBoundary = 0.0f;  // the value gradient at which an unchanged place keeps its whole share
    float unchangedOpacity = 1.0f;
    // The time-steps that take part, first and last inclusive (the scene's exposure, or a solo step).
    glm::ivec2 exposedSteps{0, std::numeric_limits<int>::max()};
    // The packed atlas (RaycastVariant::walk PackedGroups).
    glm::ivec3 sharedValiditySize{1};
    int packedGroupCount = 0;
    glm::ivec3 packedAtlasSize{1};
    // Lit-sphere styles (RaycastVariant::styled): each track's node range, the view rotation and
    // the style-image footprint of a pixel.
    std::array<glm::ivec2, contract::STYLE_TRACK_COUNT> styleTracks{};
    glm::mat3 worldToView{1.0f};
    float styleFootprint = 0.0f;
    // Rays are clipped to this world box (FrameOptions::clipBox); the default holds everything.
    glm::vec3 clipLower{-std::numeric_limits<float>::max()};
    glm::vec3 clipUpper{std::numeric_limits<float>::max()};
    glm::vec3 seriesLower{0.0f};
    glm::vec3 seriesUpper{0.0f};
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
    void draw(const RaycastVariant& variant, const RaycastParameters& parameters);
    // Counters of the last draw with collectStatistics (waits for the GPU).
    RaycastStatistics lastStatistics() const;
    // Rays of the last draw that stopped before their exit and below the termination opacity:
    // cut short by the driver's limit on loop passes (llvmpipe), so their pixels are incomplete.
    // Counted in every draw (waits for the GPU).
    std::uint32_t lastCutShortRays() const;

private:
    const Program& programFor(const RaycastVariant& variant);

    const ShaderLibrary& shaders_;
    std::map<RaycastVariant, Program> programs_;
    VertexArray emptyVertexArray_;
    Buffer statistics_;
};

}  // namespace tstyles
