// Compiling the raycasting program variants and drawing the raycasting pass.
#include "tstyles/render/raycaster.h"

#include <array>
#include <string>

#include "tstyles/render/bindings.h"
#include "tstyles/render/brick_occupancy.h"
#include "tstyles/render/transfer_tables.h"

namespace tstyles {
namespace {

int compositorDefine(TemporalCompositor compositor) {
    switch (compositor) {
        case TemporalCompositor::MaxIntensityProjection: return 0;
        case TemporalCompositor::Average: return 1;
        case TemporalCompositor::MaxDensityChange: return 2;
    }
    return 0;
}

int finalModeValue(FinalMode mode) {
    switch (mode) {
        case FinalMode::Stf: return 0;
        case FinalMode::Tstf: return 1;
        case FinalMode::Modulate: return 2;
    }
    return 2;
}

// PACKED_VALIDITY in shaders/packed_time_steps.glsl.
int packedValidityDefine(PackedValidity validity) {
    switch (validity) {
    case PackedValidity::None: return 0;
    case PackedValidity::PerGroup: return 1;
    case PackedValidity::Shared: return 2;
    }
    return 0;
}

// The shader keeps per-ray arrays of the time-steps it meets; their size is a compile-time
// constant, rounded up so that a few more or fewer time-steps reuse the same program.
int arrayCapacity(int timeStepCount) {
    int capacity = 8;
    while (capacity < timeStepCount) capacity *= 2;
    return capacity;
}

}  // namespace

namespace {
// The Statistics block of shaders/raycast.frag: rays, samples, fetches (64-bit pairs, filled with
// COLLECT_STATISTICS) and rays cut short.
constexpr std::size_t kStatisticsWords = 7;
}  // namespace

Raycaster::Raycaster(const ShaderLibrary& shaders)
    : shaders_(shaders), emptyVertexArray_(VertexArray::create()), statistics_(Buffer::create()) {
    const std::array<std::uint32_t, kStatisticsWords> zero{};
    statistics_.setData(std::as_bytes(std::span(zero)), GL_DYNAMIC_READ);
}

const Program& Raycaster::programFor(const RaycastParameters& parameters) {
    const int capacity = arrayCapacity(parameters.timeStepCount);
    const auto key = std::make_tuple(compositorDefine(parameters.compositor), parameters.collectStatistics,
                                     parameters.styled, parameters.naive, parameters.masks,
                                     parameters.allAffine, parameters.structuredGrids, parameters.packedAligned,
                                     parameters.packedValidity, capacity, parameters.unevenAxes);
    auto found = programs_.find(key);
    if (found != programs_.end()) return found->second;
    const ShaderDefines defines = {
        {"TEMPORAL_COMPOSITOR", std::to_string(compositorDefine(parameters.compositor))},
        {"COLLECT_STATISTICS", parameters.collectStatistics ? "1" : "0"},
        {"MAX_TIME_STEPS", std::to_string(capacity)},
        {"STYLED", parameters.styled ? "1" : "0"},
        {"NAIVE_RAYCASTER", parameters.naive ? "1" : "0"},
        {"HAS_MASKS", parameters.masks ? "1" : "0"},
        {"ALL_AFFINE", parameters.allAffine ? "1" : "0"},
        {"STRUCTURED_GRIDS", parameters.structuredGrids ? "1" : "0"},
        {"PACKED_ALIGNED", parameters.packedAligned ? "1" : "0"},
        {"BRICK_CELLS", std::to_string(kBrickSize)},
        {"PACKED_VALIDITY", std::to_string(packedValidityDefine(parameters.packedValidity))},
        {"UNEVEN_AXES", parameters.unevenAxes ? "1" : "0"},
    };
    auto program = Program::build(shaders_, {{GL_VERTEX_SHADER, "fullscreen.vert"},
                                             {GL_FRAGMENT_SHADER, "raycast.frag"}},
                                  defines);
    return programs_.emplace(key, std::move(program)).first->second;
}

void Raycaster::draw(const RaycastParameters& parameters) {
    const Program& program = programFor(parameters);
    program.set("inverseViewProjection", parameters.inverseViewProjection);
    program.set("viewportSize", glm::vec2(parameters.viewport));
    program.set("timeStepCount", parameters.timeStepCount);
    program.set("exposedSteps", parameters.exposedSteps);
    program.set("inverseAtlasSize", 1.0f / glm::vec3(parameters.atlasSize));
    program.set("transferTableSize", float(kTransferTableSize));
    program.set("stepLength", parameters.stepLength);
    program.set("referenceLength", parameters.referenceLength);
    program.set("terminationOpacity", parameters.terminationOpacity);
    program.set("background", parameters.background);
    program.set("finalMode", finalModeValue(parameters.finalMode));
    program.set("changeRange", parameters.changeRange);
    if (parameters.packedAligned) {
        program.set("packedGroupCount", parameters.packedGroupCount);
        program.set("inversePackedAtlasSize", 1.0f / glm::vec3(parameters.packedAtlasSize));
        if (parameters.packedValidity == PackedValidity::Shared)
            program.set("inverseSharedValiditySize", 1.0f / glm::vec3(parameters.sharedValiditySize));
    }
    if (parameters.styled) {
        glProgramUniform2iv(program.id(), glGetUniformLocation(program.id(), "styleTracks"), 3,
                            &parameters.styleTracks[0].x);
        program.set("worldToView", parameters.worldToView);
        program.set("styleFootprint", parameters.styleFootprint);
    }
    statistics_.clearToZero();
    statistics_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::kStatisticsBuffer);
    glViewport(0, 0, parameters.viewport.x, parameters.viewport.y);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    program.use();
    emptyVertexArray_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

RaycastStatistics Raycaster::lastStatistics() const {
    std::array<std::uint32_t, 6> counters = {0, 0, 0, 0, 0, 0};
    // The counters were written by shader atomics: make them visible to the read-back.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(statistics_.id(), 0, sizeof counters, counters.data());
    auto counter = [&](int index) {
        return std::uint64_t(counters[2 * index]) | (std::uint64_t(counters[2 * index + 1]) << 32);
    };
    return {counter(0), counter(1), counter(2)};
}

std::uint32_t Raycaster::lastCutShortRays() const {
    std::uint32_t cutShort = 0;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(statistics_.id(), 6 * sizeof(std::uint32_t), sizeof cutShort, &cutShort);
    return cutShort;
}

}  // namespace tstyles
