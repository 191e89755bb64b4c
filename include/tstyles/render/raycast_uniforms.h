// The C++ side of shaders/raycast_uniforms.glsl: each uniform of the raycasting program as a typed
// name (raycast_uniform::stepLength is a UniformName<float>), so that Program::set takes it with a
// value of its GLSL type only. The names are written once, in that file.
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

#include "tstyles/gl/program.h"
#include "tstyles/render/shader_contract.h"

namespace tstyles::raycast_uniform {

using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using ivec2 = glm::ivec2;
using ivec3 = glm::ivec3;
using mat3 = glm::mat3;
using mat4 = glm::mat4;

#define RAYCAST_UNIFORM(type, name) inline constexpr UniformName<type> name{#name};
#define RAYCAST_UNIFORM_ARRAY(type, name, count) \
    inline constexpr UniformArrayName<type, std::size_t(contract::count)> name{#name};
#include "raycast_uniforms.glsl"
#undef RAYCAST_UNIFORM
#undef RAYCAST_UNIFORM_ARRAY

}  // namespace tstyles::raycast_uniform
