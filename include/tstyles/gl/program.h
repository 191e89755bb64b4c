// A linked GLSL program built from shader files, with uniforms set by name.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/gl/handle.h"
#include "tstyles/gl/shader_preprocessor.h"

namespace tstyles {

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

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
