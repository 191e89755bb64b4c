// #include resolution with #line bookkeeping for GLSL.
#include "tstyles/gl/shader_preprocessor.h"

#include <regex>
#include <sstream>
#include <stdexcept>

namespace tstyles {
namespace {

struct Flattener {
    const ShaderFileReader& reader;
    FlattenedShader result;
    std::vector<std::string> includeStack;

    int fileNumber(const std::string& name) {
        for (std::size_t i = 0; i < result.files.size(); ++i)
            if (result.files[i] == name) return int(i);
        result.files.push_back(name);
        return int(result.files.size() - 1);
    }

    bool alreadyIncluded(const std::string& name) const {
        for (const auto& file : result.files)
            if (file == name) return true;
        return false;
    }

    static std::optional<std::string> includeTarget(const std::string& line) {
        static const std::regex pattern(R"(^\s*#\s*include\s+"([^"]+)\"\s*(//.*)?$)");
        std::smatch match;
        if (std::regex_match(line, match, pattern)) return match[1].str();
        return std::nullopt;
    }

    void append(const std::string& name, const std::string& source, std::ostringstream& out,
                const std::vector<std::pair<std::string, std::string>>* defines) {
        const int number = fileNumber(name);
        includeStack.push_back(name);
        std::istringstream lines(source);
        std::string line;
        int lineNumber = 0;
        bool versionSeen = defines == nullptr;
        if (defines == nullptr) out << "#line 1 " << number << "\n";
        while (std::getline(lines, line)) {
            ++lineNumber;
            if (!versionSeen) {
                if (line.rfind("#version", 0) != 0) {
                    if (line.find_first_not_of(" \t\r") == std::string::npos ||
                        line.rfind("//", 0) == 0)
                        continue;
                    throw std::runtime_error(name + ":" + std::to_string(lineNumber) +
                                             ": a shader stage must begin with #version");
                }
                versionSeen = true;
                out << line << "\n";
                for (const auto& [key, value] : *defines) out << "#define " << key << " " << value << "\n";
                out << "#line " << lineNumber + 1 << " " << number << "\n";
                continue;
            }
            if (auto target = includeTarget(line)) {
                for (const auto& open : includeStack)
                    if (open == *target)
                        throw std::runtime_error(name + ":" + std::to_string(lineNumber) +
                                                 ": include cycle through \"" + *target + "\"");
                if (!alreadyIncluded(*target)) {
                    auto text = reader(*target);
                    if (!text)
                        throw std::runtime_error(name + ":" + std::to_string(lineNumber) +
                                                 ": included file \"" + *target + "\" not found");
                    append(*target, *text, out, nullptr);
                }
                out << "#line " << lineNumber + 1 << " " << number << "\n";
                continue;
            }
            out << line << "\n";
        }
        if (!versionSeen) throw std::runtime_error(name + ": a shader stage must begin with #version");
        includeStack.pop_back();
    }
};

}  // namespace

FlattenedShader flattenShader(const std::string& entryName, const ShaderFileReader& libraryReader,
                              const std::vector<std::pair<std::string, std::string>>& defines,
                              const ShaderModules& modules) {
    const ShaderFileReader reader = [&](const std::string& name) -> std::optional<std::string> {
        for (const auto& module : modules)
            if (module.includedAs == name) return module.text ? module.text : libraryReader(module.file);
        return libraryReader(name);
    };
    auto source = reader(entryName);
    if (!source) throw std::runtime_error("shader file \"" + entryName + "\" not found");
    Flattener flattener{reader, {}, {}};
    std::ostringstream out;
    flattener.append(entryName, *source, out, &defines);
    flattener.result.text = out.str();
    for (auto& file : flattener.result.files)
        for (const auto& module : modules)
            if (module.includedAs == file) file = module.file;
    return flattener.result;
}

std::string FlattenedShader::translateLog(const std::string& log) const {
    static const std::regex mesa(R"((\d+):(\d+)\((\d+)\):)");
    static const std::regex nvidia(R"((\d+)\((\d+)\) :)");
    std::istringstream lines(log);
    std::ostringstream out;
    std::string line;
    auto fileName = [&](const std::string& number) {
        const auto index = std::stoul(number);
        return index < files.size() ? files[index] : "source " + number;
    };
    while (std::getline(lines, line)) {
        std::smatch match;
        if (std::regex_search(line, match, mesa))
            line = match.prefix().str() + fileName(match[1]) + ":" + match[2].str() + ":" +
                   match[3].str() + ":" + match.suffix().str();
        else if (std::regex_search(line, match, nvidia))
            line = match.prefix().str() + fileName(match[1]) + ":" + match[2].str() + ":" +
                   match.suffix().str();
        out << line << "\n";
    }
    return out.str();
}

}  // namespace tstyles
