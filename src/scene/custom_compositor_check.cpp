// The sandbox of a scene's own compositor: a token-level check of its GLSL body.
#include "custom_compositor_check.h"

#include <cctype>
#include <set>
#include <string_view>
#include <vector>

namespace tstyles {
namespace {

struct Token {
    std::string text;
    int line;
    bool identifier;
};

// Identifiers, numbers and one-character punctuation, without comments; `#` stays a token.
std::vector<Token> tokenize(const std::string& code) {
    std::vector<Token> tokens;
    int line = 1;
    std::size_t i = 0;
    while (i < code.size()) {
        const char c = code[i];
        if (c == '\n') ++line;
        if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
        if (code.compare(i, 2, "//") == 0) {
            while (i < code.size() && code[i] != '\n') ++i;
            continue;
        }
        if (code.compare(i, 2, "/*") == 0) {
            i += 2;
            while (i < code.size() && code.compare(i, 2, "*/") != 0) line += code[i++] == '\n' ? 1 : 0;
            i += 2;
            continue;
        }
        const std::size_t begin = i;
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            while (i < code.size() && (std::isalnum(static_cast<unsigned char>(code[i])) || code[i] == '_')) ++i;
            tokens.push_back({code.substr(begin, i - begin), line, true});
        } else if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < code.size() &&
                                                                   std::isdigit(static_cast<unsigned char>(code[i + 1])))) {
            while (i < code.size() && (std::isalnum(static_cast<unsigned char>(code[i])) || code[i] == '.')) ++i;
            tokens.push_back({code.substr(begin, i - begin), line, false});
        } else {
            tokens.push_back({std::string(1, c), line, false});
            ++i;
        }
    }
    return tokens;
}

const std::set<std::string_view> kInputs{"count", "density", "hasData", "inMask", "stf", "time", "MAX_TIME_STEPS"};

const std::set<std::string_view> kTypes{"float", "int", "uint", "bool", "vec2", "vec3", "vec4", "ivec2", "ivec3",
                                        "ivec4", "bvec2", "bvec3", "bvec4", "mat2", "mat3", "mat4"};

const std::set<std::string_view> kKeywords{"if", "else", "for", "return", "const", "true", "false", "break", "continue"};

// GLSL's built-in functions that only compute: no textures, images, atomics or barriers.
const std::set<std::string_view> kBuiltins{
    "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "asinh", "acosh",
    "atanh", "pow", "exp", "log", "exp2", "log2", "sqrt", "inversesqrt", "abs", "sign", "floor", "trunc", "round",
    "roundEven", "ceil", "fract", "mod", "min", "max", "clamp", "mix", "step", "smoothstep", "isnan", "isinf",
    "fma", "length", "distance", "dot", "cross", "normalize", "lessThan", "lessThanEqual", "greaterThan",
    "greaterThanEqual", "equal", "notEqual", "any", "all", "not"};

const std::set<std::string_view> kForbiddenKeywords{"while", "do", "discard", "switch", "struct", "uniform",
                                                    "buffer", "shared", "layout", "in", "out", "inout"};

std::string quoted(const std::string& text) { return "\"" + text + "\""; }

// `for (int NAME = ...; NAME < count; ++NAME)` (or NAME++), starting at tokens[at] ("for"); the
// index just past its closing parenthesis, or nothing.
std::optional<std::size_t> boundedLoopHeader(const std::vector<Token>& tokens, std::size_t at, std::string& name) {
    auto is = [&](std::size_t index, std::string_view text) { return index < tokens.size() && tokens[index].text == text; };
    if (!is(at + 1, "(") || !is(at + 2, "int") || at + 3 >= tokens.size() || !tokens[at + 3].identifier) return {};
    name = tokens[at + 3].text;
    std::size_t i = at + 4;
    int depth = 0;
    while (i < tokens.size() && !(depth == 0 && tokens[i].text == ";")) {
        depth += tokens[i].text == "(" ? 1 : tokens[i].text == ")" ? -1 : 0;
        ++i;
    }
    if (!is(i + 1, name) || !is(i + 2, "<") || !is(i + 3, "count") || !is(i + 4, ";")) return {};
    const std::size_t increment = i + 5;
    const bool prefix = is(increment, "+") && is(increment + 1, "+") && is(increment + 2, name);
    const bool postfix = is(increment, name) && is(increment + 1, "+") && is(increment + 2, "+");
    if (!(prefix || postfix) || !is(increment + 3, ")")) return {};
    return increment + 4;
}

// Whether tokens[at] is written: `NAME = ...`, a compound assignment (`+=`, `%=`, `<<=`, ...) or
// an increment or decrement before or after it.
bool isAssignmentTo(const std::vector<Token>& tokens, std::size_t at) {
    auto text = [&](std::size_t index) { return index < tokens.size() ? tokens[index].text : std::string(); };
    const std::string next = text(at + 1);
    const std::string after = text(at + 2);
    if (next == "=" && after != "=") return true;
    static const std::set<std::string_view> kCompoundOperators{"+", "-", "*", "/", "%", "&", "|", "^"};
    if (kCompoundOperators.contains(next) && after == "=") return true;
    if ((next == "+" || next == "-") && after == next) return true;
    if ((next == "<" || next == ">") && after == next && text(at + 3) == "=") return true;
    const std::string before = at >= 1 ? text(at - 1) : "";
    const std::string beforeThat = at >= 2 ? text(at - 2) : "";
    return (before == "+" && beforeThat == "+") || (before == "-" && beforeThat == "-");
}

}  // namespace

std::optional<SandboxViolation> findSandboxViolation(const std::string& code) {
    const std::vector<Token> tokens = tokenize(code);
    std::set<std::string> declared;
    std::set<std::string> loopNames;
    std::set<std::size_t> loopHeaderTokens;
    // Within a declaration statement (`float a = 1.0, b;`), at which bracket depth it began.
    int depth = 0;
    constexpr int kNoDeclaration = -1;
    int declarationDepth = kNoDeclaration;
    int braces = 0;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const Token& token = tokens[i];
        if (token.text == "(" || token.text == "[") ++depth;
        if (token.text == ")" || token.text == "]") --depth;
        if (token.text == ";") declarationDepth = kNoDeclaration;
        if (token.text == "{") ++braces;
        // The code is a function body: closing more than it opened would end the function.
        if (token.text == "}" && --braces < 0)
            return SandboxViolation{token.line, "a \"}\" without its \"{\": the code is a function body"};
        if (token.text == "#")
            return SandboxViolation{token.line, "preprocessor directives are not allowed in a compositor"};
        if (!token.identifier) continue;
        if (kForbiddenKeywords.contains(token.text))
            return SandboxViolation{token.line, quoted(token.text) + " is not allowed in a compositor (loops are "
                                                "\"for (int i = 0; i < count; ++i)\")"};
        if (token.text == "for") {
            std::string name;
            const auto end = boundedLoopHeader(tokens, i, name);
            if (!end)
                return SandboxViolation{token.line, "a loop must read \"for (int NAME = START; NAME < count; ++NAME)\": "
                                                    "its bound is the number of time-steps"};
            declared.insert(name);
            loopNames.insert(name);
            for (std::size_t k = i; k < *end; ++k) loopHeaderTokens.insert(k);
            continue;
        }
        if (i > 0 && tokens[i - 1].text == ".") continue;  // a swizzle or a field
        if (kTypes.contains(token.text) || kKeywords.contains(token.text) || kBuiltins.contains(token.text) ||
            kInputs.contains(token.text))
            continue;
        // A declaration: a name after a type, or after a comma of the same declaration statement.
        const bool afterType = i > 0 && kTypes.contains(tokens[i - 1].text);
        const bool afterDeclarationComma =
            i > 0 && tokens[i - 1].text == "," && declarationDepth != kNoDeclaration && declarationDepth == depth;
        if (afterType || afterDeclarationComma) {
            if (afterType) declarationDepth = depth;
            declared.insert(token.text);
            continue;
        }
        if (declared.contains(token.text)) continue;
        return SandboxViolation{token.line, quoted(token.text) +
                                                " is not available to a compositor: it may use its inputs (count, "
                                                "density, hasData, inMask, stf, time), its own variables and GLSL's "
                                                "built-in math functions"};
    }
    if (braces > 0)
        return SandboxViolation{tokens.back().line, "a \"{\" without its \"}\": the code is a function body"};
    for (std::size_t i = 0; i < tokens.size(); ++i)
        if (tokens[i].identifier && loopNames.contains(tokens[i].text) && !loopHeaderTokens.contains(i) &&
            isAssignmentTo(tokens, i))
            return SandboxViolation{tokens[i].line, "the loop variable " + quoted(tokens[i].text) +
                                                        " may change only in its loop's header"};
    return std::nullopt;
}

}  // namespace tstyles
