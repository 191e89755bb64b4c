// Build-time tool: writes a shader stage with its #includes resolved, for glslangValidator.
// Usage: shader_flatten SHADER_DIR ENTRY_NAME OUTPUT_FILE
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "tstyles/gl/shader_preprocessor.h"

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: shader_flatten SHADER_DIR ENTRY_NAME OUTPUT_FILE\n";
        return 2;
    }
    const std::filesystem::path directory = argv[1];
    auto reader = [&](const std::string& name) -> std::optional<std::string> {
        std::ifstream in(directory / name, std::ios::binary);
        if (!in) return std::nullopt;
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    };
    try {
        const auto flat = tstyles::flattenShader(argv[2], reader);
        std::ofstream out(argv[3], std::ios::binary | std::ios::trunc);
        out << flat.text;
        // Beside it, the file behind each source-string number, one per line, so that the build
        // can name files in glslangValidator's messages.
        std::ofstream names(std::string(argv[3]) + ".files", std::ios::trunc);
        for (const auto& file : flat.files) names << file << "\n";
        if (!out || !names) {
            std::cerr << "shader_flatten: cannot write " << argv[3] << "\n";
            return 1;
        }
    } catch (const std::exception& error) {
        std::cerr << "shaders/" << error.what() << "\n";
        return 1;
    }
    return 0;
}
