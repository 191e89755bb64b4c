// #include resolution with #line bookkeeping for GLSL.
#include "tstyles/gl/shader_preprocessor.h"

#include <cctype>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace tstyles {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::size_t skipBlanks(const std::string& text, std::size_t at) {
    while (at < text.size() && isBlank(text[at])) ++at;
    return at;
}

// The end of the run of digits starting at `at` (== at when there is none).
std::size_t digitsEnd(const std::string& text, std::size_t at) {
    while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at]))) ++at;
    return at;
}

// Where a driver's log line names a source: Mesa "FILE:LINE(COLUMN):", NVIDIA "FILE(LINE) :".
struct LogLocation {
    std::size_t begin = 0, end = 0;
    std::string file, line, column;  // column empty for NVIDIA's form
};

std::optional<LogLocation> findLogLocation(const std::string& text) {
    for (std::size_t start = 0; start < text.size(); ++start) {
        if (!std::isdigit(static_cast<unsigned char>(text[start])) ||
            (start > 0 && std::isdigit(static_cast<unsigned char>(text[start - 1]))))
            continue;
        const std::size_t fileEnd = digitsEnd(text, start);
        LogLocation found{start, 0, text.substr(start, fileEnd - start), "", ""};
        if (fileEnd < text.size() && text[fileEnd] == ':') {
            const std::size_t lineEnd = digitsEnd(text, fileEnd + 1);
            if (lineEnd > fileEnd + 1 && lineEnd < text.size() && text[lineEnd] == '(') {
                const std::size_t columnEnd = digitsEnd(text, lineEnd + 1);
                if (columnEnd > lineEnd + 1 && text.compare(columnEnd, 2, "):") == 0) {
                    found.line = text.substr(fileEnd + 1, lineEnd - fileEnd - 1);
                    found.column = text.substr(lineEnd + 1, columnEnd - lineEnd - 1);
                    found.end = columnEnd + 2;
                    return found;
                }
            }
        }
        if (fileEnd < text.size() && text[fileEnd] == '(') {
            const std::size_t lineEnd = digitsEnd(text, fileEnd + 1);
            if (lineEnd > fileEnd + 1 && text.compare(lineEnd, 3, ") :") == 0) {
                found.line = text.substr(fileEnd + 1, lineEnd - fileEnd - 1);
                found.end = lineEnd + 3;
                return found;
            }
        }
    }
    return std::nullopt;
}

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
        // #include "NAME", blanks allowed around '#', an optional // comment after.
        std::size_t at = skipBlanks(line, 0);
        if (at >= line.size() || line[at] != '#') return std::nullopt;
        at = skipBlanks(line, at + 1);
        if (line.compare(at, 7, "include") != 0) return std::nullopt;
        const std::size_t afterKeyword = at + 7;
        at = skipBlanks(line, afterKeyword);
        if (at == afterKeyword || at >= line.size() || line[at] != '"') return std::nullopt;
        const std::size_t close = line.find('"', at + 1);
        if (close == std::string::npos || close == at + 1) return std::nullopt;
        const std::size_t rest = skipBlanks(line, close + 1);
        if (rest < line.size() && line.compare(rest, 2, "//") != 0) return std::nullopt;
        return line.substr(at + 1, close - at - 1);
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
    std::istringstream lines(log);
    std::ostringstream out;
    std::string line;
    auto fileName = [&](const std::string& number) {
        const auto index = std::stoul(number);
        return index < files.size() ? files[index] : "source " + number;
    };
    while (std::getline(lines, line)) {
        if (const auto found = findLogLocation(line))
            line = line.substr(0, found->begin) + fileName(found->file) + ":" + found->line + ":" +
                   (found->column.empty() ? "" : found->column + ":") + line.substr(found->end);
        out << line << "\n";
    }
    return out.str();
}

}  // namespace tstyles
