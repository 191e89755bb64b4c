// The C++ side of the C++/GLSL contract: shaders/contract.glsl, included here with its GLSL types
// mapped to glm, so that binding points, enum codes and std430 structs are written once.
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

namespace tstyles::contract {

using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;

#define CONTRACT_CONSTANT(type, name, value) inline constexpr type name = value;
#include "contract.glsl"
#undef CONTRACT_CONSTANT

// std430 gives these structs of 16-byte members the size C++ gives them; a member of another type
// added to contract.glsl would break that, and these stop the build.
static_assert(sizeof(TimeStepInfo) == 64 + 9 * 16);
static_assert(sizeof(ProxyBox) == 64 + 16);
static_assert(sizeof(ProxyVertex) == 2 * 16);
static_assert(sizeof(StructuredGridInfo) == 2 * 16);
static_assert(sizeof(UnevenAxisInfo) == 4 * 16);
static_assert(sizeof(StyleNode) == 2 * 16);
static_assert(alignof(TimeStepInfo) <= 16 && sizeof(glm::vec4) == 16 && sizeof(glm::mat4) == 64);

}  // namespace tstyles::contract
