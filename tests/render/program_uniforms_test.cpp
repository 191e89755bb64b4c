// The raycasting program's uniforms, declared once (shaders/raycast_uniforms.glsl): every typed
// name is declared in the programs that set it, a name no stage declares is refused, and the
// compiler-log reading that names a scene's own compositor code.
#include <array>
#include <stdexcept>

#include <gtest/gtest.h>

#include "render_test_support.h"
#include "tstyles/gl/program.h"
#include "tstyles/render/raycast_uniforms.h"
#include "tstyles/render/raycast_variant.h"

namespace tstyles::testing {
namespace {

template <class T>
void setDefault(const Program& program, UniformName<T> uniform) {
    program.set(uniform, T{});
}

template <class T, std::size_t count>
void setDefault(const Program& program, UniformArrayName<T, count> uniform) {
    program.set(uniform, std::array<T, count>{});
}

// Sets every uniform of raycast_uniforms.glsl; each must be declared in the program.
void setEveryRaycastUniform(const Program& program) {
#define RAYCAST_UNIFORM(type, name) setDefault(program, raycast_uniform::name);
#define RAYCAST_UNIFORM_ARRAY(type, name, count) setDefault(program, raycast_uniform::name);
#include "raycast_uniforms.glsl"
#undef RAYCAST_UNIFORM
#undef RAYCAST_UNIFORM_ARRAY
}

Program raycastProgram(const RaycastVariant& variant) {
    testRenderer();  // the context
    return Program::build(ShaderLibrary::embedded(),
                          {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "raycast.frag"}},
                          variant.defines(), variant.modules());
}

TEST(RaycastUniforms, EveryNameIsDeclaredInEveryRaycastingProgram) {
    // One program per walk, styled and with unchanged places and a compositor with options, and the
    // parts bench --stages times: each declares every name (those it does not use are optimised
    // away, and setting them writes nowhere).
    RaycastVariant packed;
    packed.compositor = compositorNamed("first-arrival");
    packed.walk = TimeStepWalk::PackedGroups;
    packed.allAffine = true;
    packed.styledTracks = 7;
    packed.unchangedTime = true;
    RaycastVariant beams;
    beams.compositor = compositorNamed("difference");
    beams.rectilinearGrids = false;
    beams.beamGrids = true;
    RaycastVariant naive;
    naive.walk = TimeStepWalk::Naive;
    for (const RaycastVariant& variant :
         {packed, beams, naive, partOf(beams, RaycastPart::March), partOf(packed, RaycastPart::RaySetup)}) {
        const Program program = raycastProgram(variant);
        EXPECT_NO_THROW(setEveryRaycastUniform(program)) << variant.describe();
    }
}

TEST(RaycastUniforms, ANameNoStageDeclaresIsRefused) {
    const Program program = raycastProgram(RaycastVariant{});
    EXPECT_THROW(program.set(UniformName<float>{"stepLenght"}, 0.5f), std::logic_error);
    EXPECT_THROW(program.set("noSuchUniform", 1), std::logic_error);
    EXPECT_NO_THROW(program.set(raycast_uniform::stepLength, 0.5f));
}

TEST(CompileLog, TheFirstErrorInTheScenesCodeIsNamedByLine) {
    const std::string mesa =
        "cannot compile shader raycast.frag (embedded shaders):\n"
        "scene.json: compositor.glsl:3:12: error: `foo' undeclared\n"
        "scene.json: compositor.glsl:5:1: error: syntax error, unexpected '}'\n"
        "raycast.frag:120:4: error: no matching function\n";
    EXPECT_EQ(firstCompileErrorIn(mesa, "scene.json: compositor.glsl"),
              "line 3: does not compile: `foo' undeclared (and 1 more errors)");
    const std::string nvidia = "own.glsl:7: error C1008: undefined variable \"x\"\n";
    EXPECT_EQ(firstCompileErrorIn(nvidia, "own.glsl"), "line 7: does not compile: C1008: undefined variable \"x\"");
    // Nothing names the code's lines: the log's first error.
    const std::string elsewhere = "cannot compile shader raycast.frag:\nraycast.frag:9:2: error: too many uniforms\n";
    EXPECT_EQ(firstCompileErrorIn(elsewhere, "own.glsl"),
              "does not compile: raycast.frag:9:2: error: too many uniforms");
}

}  // namespace
}  // namespace tstyles::testing
