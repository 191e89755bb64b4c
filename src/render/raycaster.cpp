// Compiling the raycasting program variants and drawing the raycasting pass.
#include "tstyles/render/raycaster.h"

#include <array>
#include <cctype>
#include <optional>
#include <sstream>
#include <string>

#include "tstyles/render/shader_contract.h"
#include "tstyles/render/brick_occupancy.h"
#include "tstyles/render/transfer_tables.h"
#include "tstyles/core/errors.h"
#include "tstyles/scene/temporal_compositors.h"

namespace tstyles {
namespace {

// One line for a compiler log about the scene's code, which compiler messages call `file`: the
// first error there as "line L: does not compile: MESSAGE" (Mesa writes "file:L:C: error: ...",
// NVIDIA "file:L: error ..."), and how many more errors followed.
struct LocatedMessage {
    std::string line;
    std::string message;
};

// ":L[:C]: [error[:]] MESSAGE" after the file name; hand-parsed, since GCC 12's <regex> does not
// build warning-free under the sanitizers.
std::optional<LocatedMessage> locatedMessage(const std::string& rest) {
    std::size_t at = 0;
    auto digits = [&] {
        const std::size_t begin = at;
        while (at < rest.size() && std::isdigit(static_cast<unsigned char>(rest[at]))) ++at;
        return rest.substr(begin, at - begin);
    };
    if (at >= rest.size() || rest[at++] != ':') return std::nullopt;
    const std::string line = digits();
    if (line.empty()) return std::nullopt;
    if (at < rest.size() && rest[at] == ':' && at + 1 < rest.size() &&
        std::isdigit(static_cast<unsigned char>(rest[at + 1]))) {
        ++at;
        digits();
    }
    if (at >= rest.size() || rest[at++] != ':') return std::nullopt;
    while (at < rest.size() && std::isspace(static_cast<unsigned char>(rest[at]))) ++at;
    if (rest.compare(at, 5, "error") == 0) {
        at += 5;
        if (at < rest.size() && rest[at] == ':') ++at;
        while (at < rest.size() && std::isspace(static_cast<unsigned char>(rest[at]))) ++at;
    }
    return LocatedMessage{line, rest.substr(at)};
}

std::string firstErrorIn(const std::string& log, const std::string& file) {
    std::istringstream lines(log);
    std::string line;
    std::string first;
    int more = 0;
    while (std::getline(lines, line)) {
        const std::size_t at = line.find(file + ":");
        if (at == std::string::npos) continue;
        const auto located = locatedMessage(line.substr(at + file.size()));
        if (!located) continue;
        if (!first.empty()) {
            more += line.find("error") != std::string::npos ? 1 : 0;
            continue;
        }
        first = "line " + located->line + ": does not compile: " + located->message;
    }
    if (first.empty()) {
        // Nothing names the code's own lines (an error the code causes in the program around it).
        std::istringstream whole(log);
        while (std::getline(whole, line) && line.find("error") == std::string::npos) {}
        return "does not compile: " + (line.empty() ? log.substr(0, log.find('\n')) : line);
    }
    return more == 0 ? first : first + " (and " + std::to_string(more) + " more errors)";
}

int finalModeCode(FinalMode mode) {
    switch (mode) {
        case FinalMode::Stf: return contract::FINAL_STF;
        case FinalMode::Tstf: return contract::FINAL_TSTF;
        case FinalMode::Modulate: return contract::FINAL_MODULATE;
    }
    return contract::FINAL_MODULATE;
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

const Program& Raycaster::programFor(const RaycastVariant& variant) {
    auto found = programs_.find(variant);
    if (found != programs_.end()) return found->second;
    const std::vector<ShaderStage> stages{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "raycast.frag"}};
    try {
        return programs_.emplace(variant, Program::build(shaders_, stages, variant.defines(), variant.modules()))
            .first->second;
    } catch (const std::runtime_error& error) {
        // With the scene's own code the compiler's complaint is about the user's input, and names its lines.
        if (variant.compositor != TemporalCompositor::Custom) throw;
        throw InputError(variant.customCodeName + ": " + firstErrorIn(error.what(), variant.customCodeName));
    }
}

void Raycaster::draw(const RaycastVariant& variant, const RaycastParameters& parameters) {
    const Program& program = programFor(variant);
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
    program.set("clipLower", parameters.clipLower);
    program.set("clipUpper", parameters.clipUpper);
    program.set("seriesLower", parameters.seriesLower);
    program.set("seriesUpper", parameters.seriesUpper);
    program.set("finalMode", finalModeCode(parameters.finalMode));
    program.set("changeRange", parameters.changeRange);
    const TemporalCompositorInfo& compositor = compositorInfo(variant.compositor);
    if (compositor.takesThreshold) program.set("compositorThreshold", parameters.compositorThreshold);
    program.set("stfVisibleRange", parameters.stfVisibleRange);
    if (compositor.takesSteps) program.set("compositorSteps", parameters.compositorSteps);
    if (variant.unchangedTime) {
        program.set("unchangedBelow", std::span<const float>(parameters.unchangedBelow));
        program.set("unchangedTie", std::span<const float>(parameters.unchangedTie));
        program.set("changedGain", parameters.changedGain);
        program.set("unchangedBoundary", parameters.unchangedBoundary);
        program.set("unchangedOpacity", parameters.unchangedOpacity);
    }
    if (variant.walk == TimeStepWalk::PackedGroups) {
        program.set("packedGroupCount", parameters.packedGroupCount);
        program.set("inversePackedAtlasSize", 1.0f / glm::vec3(parameters.packedAtlasSize));
        if (variant.packedValidity == PackedValidity::Shared)
            program.set("inverseSharedValiditySize", 1.0f / glm::vec3(parameters.sharedValiditySize));
    }
    if (variant.styled()) {
        glProgramUniform2iv(program.id(), glGetUniformLocation(program.id(), "styleTracks"), 3,
                            &parameters.styleTracks[0].x);
        program.set("worldToView", parameters.worldToView);
        program.set("styleFootprint", parameters.styleFootprint);
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
