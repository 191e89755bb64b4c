// Shader compilation and linking with file-and-line error messages.
#include "tstyles/gl/program.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "tstyles/gl/embedded_shaders.h"

namespace tstyles {

ShaderLibrary ShaderLibrary::embedded() { return ShaderLibrary(); }

ShaderLibrary ShaderLibrary::fromDirectory(const std::filesystem::path& directory) {
    ShaderLibrary library;
    library.directory_ = directory;
    return library;
}

ShaderLibrary ShaderLibrary::fromEnvironment(const std::optional<std::filesystem::path>& overrideDirectory) {
    if (const char* directory = std::getenv("TSTYLES_SHADER_DIR"); directory != nullptr && *directory != 0)
        return fromDirectory(directory);
    if (overrideDirectory) return fromDirectory(*overrideDirectory);
    return embedded();
}

std::string ShaderLibrary::describe() const {
    return directory_ ? "shaders from " + directory_->string() : "embedded shaders";
}

FlattenedShader ShaderLibrary::flatten(const std::string& entry, const ShaderDefines& defines) const {
    ShaderFileReader reader;
    if (directory_) {
        reader = [directory = *directory_](const std::string& name) -> std::optional<std::string> {
            std::ifstream in(directory / name, std::ios::binary);
            if (!in) return std::nullopt;
            std::ostringstream text;
            text << in.rdbuf();
            return text.str();
        };
    } else {
        reader = [](const std::string& name) -> std::optional<std::string> {
            const auto& files = embeddedShaderFiles();
            const auto found = files.find(name);
            if (found == files.end()) return std::nullopt;
            return std::string(found->second);
        };
    }
    try {
        return flattenShader(entry, reader, defines);
    } catch (const std::runtime_error& error) {
        throw std::runtime_error("shader " + entry + " (" + describe() + "): " + error.what());
    }
}

namespace {

GlHandle<ShaderTraits> compileStage(const ShaderLibrary& library, const ShaderStage& stage,
                                    const ShaderDefines& defines) {
    const FlattenedShader source = library.flatten(stage.file, defines);
    GlHandle<ShaderTraits> shader(glCreateShader(stage.type));
    const char* text = source.text.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint compiled = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &compiled);
    if (compiled != GL_TRUE) {
        GLint length = 0;
        glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(std::max(length, 1)), '\0');
        glGetShaderInfoLog(shader.id(), GLsizei(log.size()), nullptr, log.data());
        throw std::runtime_error("cannot compile shader " + stage.file + " (" + library.describe() +
                                 "):\n" + source.translateLog(log.c_str()));
    }
    return shader;
}

}  // namespace

Program Program::build(const ShaderLibrary& library, const std::vector<ShaderStage>& stages,
                       const ShaderDefines& defines) {
    std::vector<GlHandle<ShaderTraits>> shaders;
    for (const auto& stage : stages) shaders.push_back(compileStage(library, stage, defines));
    Program program(glCreateProgram());
    for (const auto& shader : shaders) glAttachShader(program.id(), shader.id());
    glLinkProgram(program.id());
    for (const auto& shader : shaders) glDetachShader(program.id(), shader.id());
    GLint linked = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program.id(), GLsizei(log.size()), nullptr, log.data());
        std::string names;
        for (const auto& stage : stages) names += " " + stage.file;
        throw std::runtime_error("cannot link program (" + names + " ):\n" + log);
    }
    return program;
}

GLint Program::location(const char* name) const {
    auto found = locations_.find(name);
    if (found != locations_.end()) return found->second;
    const GLint location = glGetUniformLocation(id(), name);
    locations_.emplace(name, location);
    return location;
}

// A uniform that the compiler optimised away has location -1; GL ignores such writes.
void Program::set(const char* name, int value) const { glProgramUniform1i(id(), location(name), value); }
void Program::set(const char* name, float value) const { glProgramUniform1f(id(), location(name), value); }
void Program::set(const char* name, const glm::vec2& value) const {
    glProgramUniform2f(id(), location(name), value.x, value.y);
}
void Program::set(const char* name, const glm::vec3& value) const {
    glProgramUniform3f(id(), location(name), value.x, value.y, value.z);
}
void Program::set(const char* name, const glm::vec4& value) const {
    glProgramUniform4f(id(), location(name), value.x, value.y, value.z, value.w);
}
void Program::set(const char* name, const glm::ivec2& value) const {
    glProgramUniform2i(id(), location(name), value.x, value.y);
}
void Program::set(const char* name, const glm::ivec3& value) const {
    glProgramUniform3i(id(), location(name), value.x, value.y, value.z);
}
void Program::set(const char* name, const glm::mat3& value) const {
    glProgramUniformMatrix3fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(value));
}
void Program::set(const char* name, const glm::mat4& value) const {
    glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace tstyles
