// Resolves `#include "file.glsl"` in shader sources and inserts `#line` directives so that a
// compiler message points at the right file and line. Used at run time and, by the build's
// shader_flatten tool, before glslangValidator checks every shader.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tstyles {

// Returns a shader file's text by its name inside shaders/, or nothing if there is no such file.
using ShaderFileReader = std::function<std::optional<std::string>(const std::string& name)>;

// What an `#include` name stands for in one program: a file of the library ("compositor.glsl" ->
// "tc_average.glsl"), or text given here (a scene's own code), which compiler messages call `file`.
struct ShaderModule {
    std::string includedAs;
    std::string file;
    std::optional<std::string> text;
};
using ShaderModules = std::vector<ShaderModule>;

struct FlattenedShader {
    std::string text;
    // Source-string number N in `#line L N` is files[N].
    std::vector<std::string> files;

    // Rewrites "N:L(C): message" (Mesa) and "N(L) : message" (NVIDIA) in a compiler log into
    // "file:L: message".
    std::string translateLog(const std::string& log) const;
};

// `defines` are inserted right after `#version` as `#define NAME VALUE`; `modules` say what some
// include names stand for (messages name the module's file). Each file is included once
// (a second include of the same file is skipped). Throws std::runtime_error naming the including
// file and line for a missing file, an include cycle or a file without `#version`.
FlattenedShader flattenShader(const std::string& entryName, const ShaderFileReader& reader,
                              const std::vector<std::pair<std::string, std::string>>& defines = {},
                              const ShaderModules& modules = {});

}  // namespace tstyles
