// Compiling the raycasting program variants and drawing the raycasting pass.
#include "tstyles/render/raycaster.h"

#include <array>
#include <string>

#include "tstyles/render/raycast_uniforms.h"
#include "tstyles/render/shader_contract.h"
#include "tstyles/render/brick_occupancy.h"
#include "tstyles/render/transfer_tables.h"
#include "tstyles/core/errors.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

int finalModeCode(FinalMode mode) {
    switch (mode) {
        case FinalMode::Stf: return contract::FINAL_STF;
        case FinalMode::Tstf: return contract::FINAL_TSTF;
        case FinalMode::Modulate: return contract::FINAL_MODULATE;
    }
    return contract::FINAL_MODULATE;
}

// The Statistics block of shaders/raycast.frag: rays, samples, fetches (64-bit pairs, filled with
// COLLECT_STATISTICS) and rays cut short.
constexpr std::size_t kStatisticsWords = 7;
}  // namespace

Raycaster::Raycaster(const ShaderLibrary& shaders)
    : shaders_(shaders), emptyVertexArray_(VertexArray::create()), statistics_(Buffer::create()) {
    const std::array<std::uint32_t, kStatisticsWords> zero{};
    statistics_.setData(std::as_bytes(std::span(zero)), GL_DYNAMIC_READ);
}

const Program& Raycaster::programFor(const RaycastVariant& variant) {
    auto found = programs_.find(variant);
    if (found != programs_.end()) return found->second;
    const std::vector<ShaderStage> stages{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "raycast.frag"}};
    try {
        return programs_.emplace(variant, Program::build(shaders_, stages, variant.defines(), variant.modules()))
            .first->second;
    } catch (const std::runtime_error& error) {
        // With the scene's own code the compiler's complaint is about the user's input, and names its lines.
        if (variant.compositor != kCustomCompositor) throw;
        throw InputError(variant.customCodeName + ": " + firstCompileErrorIn(error.what(), variant.customCodeName));
    }
}

void Raycaster::draw(const RaycastVariant& variant, const RaycastParameters& parameters) {
    const Program& program = programFor(variant);
    namespace u = raycast_uniform;
    program.set(u::inverseViewProjection, parameters.inverseViewProjection);
    program.set(u::viewportSize, glm::vec2(parameters.viewport));
    program.set(u::timeStepCount, parameters.timeStepCount);
    program.set(u::exposedSteps, parameters.exposedSteps);
    program.set(u::inverseAtlasSize, 1.0f / glm::vec3(parameters.atlasSize));
    program.set(u::transferTableSize, float(kTransferTableSize));
    program.set(u::stepLength, parameters.stepLength);
    program.set(u::referenceLength, parameters.referenceLength);
    program.set(u::terminationOpacity, parameters.terminationOpacity);
    program.set(u::background, parameters.background);
    program.set(u::clipLower, parameters.clipLower);
    program.set(u::clipUpper, parameters.clipUpper);
    program.set(u::seriesLower, parameters.seriesLower);
    program.set(u::seriesUpper, parameters.seriesUpper);
    program.set(u::finalMode, finalModeCode(parameters.finalMode));
    program.set(u::changeRange, parameters.changeRange);
    program.set(u::stfVisibleRange, parameters.stfVisibleRange);
    for (const auto* options : {&parameters.compositorOptions, &parameters.rayOptions})
        for (const ModuleOptionUniform& option : *options)
            std::visit([&](const auto& value) { program.set(option.name, value); }, option.value);
    if (variant.unchangedTime) {
        program.set(u::unchangedBelow, parameters.unchangedBelow);
        program.set(u::unchangedTie, parameters.unchangedTie);
        program.set(u::changedGain, parameters.changedGain);
        program.set(u::unchangedBoundary, parameters.unchangedBoundary);
        program.set(u::unchangedOpacity, parameters.unchangedOpacity);
    }
    if (variant.walk == TimeStepWalk::PackedGroups) {
        program.set(u::packedGroupCount, parameters.packedGroupCount);
        program.set(u::inversePackedAtlasSize, 1.0f / glm::vec3(parameters.packedAtlasSize));
        if (variant.packedValidity == PackedValidity::Shared)
            program.set(u::inverseSharedValiditySize, 1.0f / glm::vec3(parameters.sharedValiditySize));
    }
    if (variant.styled()) {
        program.set(u::styleTracks, parameters.styleTracks);
        program.set(u::worldToView, parameters.worldToView);
        program.set(u::styleFootprint, parameters.styleFootprint);
    }
    statistics_.clearToZero();
    statistics_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::STATISTICS_BUFFER);
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
