// Shader compilation and linking with file-and-line error messages.
#include "tstyles/gl/program.h"

#include <cctype>
#include <cstdlib>
#include <iterator>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "tstyles/gl/embedded_shaders.h"

namespace tstyles {

namespace {

// A compiler message's line in a file and its text.
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

}  // namespace

std::string firstCompileErrorIn(const std::string& log, const std::string& file) {
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

FlattenedShader ShaderLibrary::flatten(const std::string& entry, const ShaderDefines& defines,
                                      const ShaderModules& modules) const {
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
        return flattenShader(entry, reader, defines, modules);
    } catch (const std::runtime_error& error) {
        throw std::runtime_error("shader " + entry + " (" + describe() + "): " + error.what());
    }
}

namespace {

bool isIdentifierCharacter(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A uniform declared through a macro, `SOMETHING_UNIFORM(TYPE, NAME)` or
// `SOMETHING_UNIFORM_ARRAY(TYPE, NAME, COUNT)` at the start of a line (shaders/raycast_uniforms.glsl):
// its NAME, or nothing.
std::optional<std::string> macroDeclaredUniform(const std::string& line) {
    const auto before = line.find_first_not_of(" \t");
    if (before == std::string::npos) return std::nullopt;
    std::size_t at = before;
    while (at < line.size() && isIdentifierCharacter(line[at])) ++at;
    const std::string macro = line.substr(before, at - before);
    const bool declares = macro.ends_with("_UNIFORM") || macro.ends_with("_UNIFORM_ARRAY");
    if (!declares || at >= line.size() || line[at] != '(') return std::nullopt;
    const auto comma = line.find(',', at);
    if (comma == std::string::npos) return std::nullopt;
    std::size_t begin = comma + 1;
    while (begin < line.size() && !isIdentifierCharacter(line[begin])) ++begin;
    std::size_t end = begin;
    while (end < line.size() && isIdentifierCharacter(line[end])) ++end;
    if (end == begin) return std::nullopt;
    return line.substr(begin, end - begin);
}

// The names of the default-block uniforms that a flattened stage declares:
// `[layout(...)] uniform TYPE NAME[, NAME...][[N]];`, or through a macro (macroDeclaredUniform).
void collectUniformNames(const std::string& text, std::unordered_set<std::string>& names) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (auto declared = macroDeclaredUniform(line)) {
            names.insert(std::move(*declared));
            continue;
        }
        const auto keyword = line.find("uniform ");
        if (keyword == std::string::npos) continue;
        const auto before = line.find_first_not_of(" \t");
        if (line.compare(before, 2, "//") == 0) continue;
        if (keyword != before && line.compare(before, 6, "layout") != 0) continue;
        const auto semicolon = line.find(';', keyword);
        if (semicolon == std::string::npos) continue;
        std::istringstream declaration(line.substr(keyword + 8, semicolon - keyword - 8));
        std::string type;
        declaration >> type;
        std::string rest((std::istreambuf_iterator<char>(declaration)), std::istreambuf_iterator<char>());
        std::size_t position = 0;
        while (position < rest.size()) {
            while (position < rest.size() && !isIdentifierCharacter(rest[position])) ++position;
            const std::size_t begin = position;
            while (position < rest.size() && isIdentifierCharacter(rest[position])) ++position;
            if (position > begin) names.insert(rest.substr(begin, position - begin));
            // Skip an array size and go to the next declarator.
            position = rest.find(',', position);
            if (position == std::string::npos) break;
        }
    }
}

GlHandle<ShaderTraits> compileStage(const ShaderLibrary& library, const ShaderStage& stage,
                                    const ShaderDefines& defines, const ShaderModules& modules,
                                    std::unordered_set<std::string>& uniformNames) {
    const FlattenedShader source = library.flatten(stage.file, defines, modules);
    collectUniformNames(source.text, uniformNames);
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
                       const ShaderDefines& defines, const ShaderModules& modules) {
    std::vector<GlHandle<ShaderTraits>> shaders;
    std::unordered_set<std::string> uniformNames;
    for (const auto& stage : stages)
        shaders.push_back(compileStage(library, stage, defines, modules, uniformNames));
    Program program(glCreateProgram());
    program.declaredUniforms_ = std::move(uniformNames);
    for (const auto& stage : stages) program.stageNames_ += (program.stageNames_.empty() ? "" : " ") + stage.file;
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
    if (location < 0 && !declaredUniforms_.contains(name))
        throw std::logic_error(std::string("uniform \"") + name + "\" is declared in no stage of the program (" +
                               stageNames_ + ")");
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
void Program::set(const char* name, std::span<const float> values) const {
    glProgramUniform1fv(id(), location(name), GLsizei(values.size()), values.data());
}
void Program::set(const char* name, std::span<const glm::ivec2> values) const {
    glProgramUniform2iv(id(), location(name), GLsizei(values.size()), glm::value_ptr(values.front()));
}
void Program::set(const char* name, const glm::mat3& value) const {
    glProgramUniformMatrix3fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(value));
}
void Program::set(const char* name, const glm::mat4& value) const {
    glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace tstyles
