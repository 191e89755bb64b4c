// A linked GLSL program built from shader files, with uniforms set by name.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/gl/handle.h"
#include "tstyles/gl/shader_preprocessor.h"

namespace tstyles {

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

// A uniform's name with its C++ type, so that Program::set takes only a value of that type (the
// raycasting program's are declared once, in shaders/raycast_uniforms.glsl).
template <class T>
struct UniformName {
    const char* name;
};
// A uniform array of `count` values of type T.
template <class T, std::size_t count>
struct UniformArrayName {
    const char* name;
};

// Where shader sources come from: the copy embedded at build time, or a shaders/ folder on disk
// (for editing shaders without rebuilding).
class ShaderLibrary {
public:
    static ShaderLibrary embedded();
    static ShaderLibrary fromDirectory(const std::filesystem::path& directory);
    // TSTYLES_SHADER_DIR if set, else `overrideDirectory` if given, else the embedded copy.
    static ShaderLibrary fromEnvironment(const std::optional<std::filesystem::path>& overrideDirectory);

    FlattenedShader flatten(const std::string& entry, const ShaderDefines& defines,
                            const ShaderModules& modules = {}) const;
    std::string describe() const;

private:
    std::optional<std::filesystem::path> directory_;
};

struct ShaderStage {
    GLenum type;
    std::string file;  // name inside shaders/, e.g. "raycast.frag"
};

// One line for the log of a program that failed to build (Program::build's message) about the code
// that compiler messages call `file` (a scene's own compositor): the first error there as
// "line L: does not compile: MESSAGE" (Mesa writes "file:L:C: error: ...", NVIDIA
// "file:L: error ..."), and how many more errors followed; without a line of that file, the log's
// first error.
std::string firstCompileErrorIn(const std::string& log, const std::string& file);

class Program {
public:
    // Compiles and links; throws std::runtime_error whose message names the shader file and line
    // of each compiler error.
    static Program build(const ShaderLibrary& library, const std::vector<ShaderStage>& stages,
                         const ShaderDefines& defines = {}, const ShaderModules& modules = {});

    GLuint id() const { return handle_.id(); }
    void use() const { glUseProgram(id()); }

    void set(const char* name, int value) const;
    void set(const char* name, float value) const;
    void set(const char* name, const glm::vec2& value) const;
    void set(const char* name, const glm::vec3& value) const;
    void set(const char* name, const glm::vec4& value) const;
    void set(const char* name, const glm::ivec2& value) const;
    void set(const char* name, const glm::ivec3& value) const;
    void set(const char* name, const glm::mat3& value) const;
    void set(const char* name, const glm::mat4& value) const;
    void set(const char* name, std::span<const float> values) const;  // a float array
    void set(const char* name, std::span<const glm::ivec2> values) const;  // an ivec2 array

    template <class T>
    void set(UniformName<T> uniform, const std::type_identity_t<T>& value) const {
        set(uniform.name, value);
    }
    template <class T, std::size_t count>
    void set(UniformArrayName<T, count> uniform, const std::array<T, count>& values) const {
        set(uniform.name, std::span<const T>(values));
    }

private:
    explicit Program(GLuint id) : handle_(id) {}
    // The uniform's location; -1 for a uniform that the compiler optimised away. A name that no
    // stage declares is a programming error (a misspelt name would otherwise write nowhere,
    // silently): std::logic_error.
    GLint location(const char* name) const;

    GlHandle<ProgramTraits> handle_;
    std::string stageNames_;  // for messages
    std::unordered_set<std::string> declaredUniforms_;
    mutable std::unordered_map<std::string, GLint> locations_;
};

}  // namespace tstyles
