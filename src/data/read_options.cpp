// The command-line spellings of ReadOptions, and the step selection they describe.
#include "tstyles/data/read_options.h"

#include <cctype>
#include <cmath>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

std::optional<std::size_t> parseIndex(const std::string& text) {
    if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
    return std::size_t(std::stoul(text));
}

std::optional<double> parseFiniteNumber(const std::string& text) {
    if (text.empty()) return std::nullopt;
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        return std::nullopt;
    }
    if (used != text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

// "125x125x25": `count` whole numbers of 1 to 5 digits joined by 'x'.
std::optional<std::vector<int>> parseSizes(const std::string& text, std::size_t count) {
    std::vector<int> sizes;
    std::size_t start = 0;
    while (sizes.size() < count) {
        std::size_t end = start;
        while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
        if (end == start || end - start > 5) return std::nullopt;
        sizes.push_back(std::stoi(text.substr(start, end - start)));
        const bool last = sizes.size() == count;
        if (last ? end != text.size() : end >= text.size() || text[end] != 'x') return std::nullopt;
        start = end + 1;
    }
    return sizes;
}

}  // namespace

StepSelection parseStepSelection(const std::string& text, const std::string& option) {
    const auto fail = [&] {
        throwInputError("", option,
                        "expected FIRST:END:STRIDE, FIRST:END or FIRST (time-step indices, END exclusive and "
                        "may be empty, STRIDE at least 1), got \"" + text + "\"");
    };
    std::vector<std::string> parts{""};
    for (char c : text) {
        if (c == ':') parts.emplace_back();
        else parts.back() += c;
    }
    if (parts.size() > 3) fail();
    StepSelection selection;
    const auto first = parts[0].empty() ? std::optional<std::size_t>(0) : parseIndex(parts[0]);
    if (!first) fail();
    selection.first = *first;
    if (parts.size() == 1) {
        selection.end = selection.first + 1;
        return selection;
    }
    if (!parts[1].empty()) {
        selection.end = parseIndex(parts[1]);
        if (!selection.end) fail();
        if (*selection.end <= selection.first) {
            throwInputError("", option, "END must be greater than FIRST, got \"" + text + "\"");
        }
    }
    if (parts.size() == 3 && !parts[2].empty()) {
        const auto stride = parseIndex(parts[2]);
        if (!stride || *stride == 0) fail();
        selection.stride = *stride;
    }
    return selection;
}

std::array<double, 2> parseValueRange(const std::string& text, const std::string& option) {
    // Split at the colon that is not a sign or exponent: "-5:1e3" has one colon.
    const auto colon = text.find(':');
    const auto low = colon == std::string::npos ? std::nullopt : parseFiniteNumber(text.substr(0, colon));
    const auto high = colon == std::string::npos ? std::nullopt : parseFiniteNumber(text.substr(colon + 1));
    if (!low || !high) throwInputError("", option, "expected LOW:HIGH (finite numbers), got \"" + text + "\"");
    if (!(*low < *high)) throwInputError("", option, "LOW must be less than HIGH, got \"" + text + "\"");
    return {*low, *high};
}

glm::ivec3 parseDims(const std::string& text, const std::string& option) {
    const auto sizes = parseSizes(text, 3);
    if (!sizes) throwInputError("", option, "expected NXxNYxNZ such as 125x125x25, got \"" + text + "\"");
    const glm::ivec3 dims{(*sizes)[0], (*sizes)[1], (*sizes)[2]};
    if (glm::any(glm::lessThan(dims, glm::ivec3(2))))
        throwInputError("", option, "each size must be at least 2, got \"" + text + "\"");
    return dims;
}

std::uint64_t parseMemorySize(const std::string& text, const std::string& option) {
    // NUMBER[.FRACTION], optional spaces, an optional K/M/G/T, an optional "B" or "iB" (any case).
    std::size_t end = 0;
    while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
    bool valid = end > 0;
    if (valid && end < text.size() && text[end] == '.') {
        const std::size_t fraction = ++end;
        while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
        valid = end > fraction;
    }
    const std::string numberText = text.substr(0, end);
    while (end < text.size() && std::isspace(static_cast<unsigned char>(text[end]))) ++end;
    std::string suffix;
    for (char c : text.substr(end)) suffix += char(std::toupper(static_cast<unsigned char>(c)));
    std::string unit;
    if (!suffix.empty() && std::string("KMGT").find(suffix[0]) != std::string::npos) {
        unit = suffix.substr(0, 1);
        suffix.erase(0, 1);
    }
    valid = valid && (suffix.empty() || suffix == "B" || suffix == "IB");
    if (!valid)
        throwInputError("", option, "expected a size such as 512M, 2G or 800000 (bytes), got \"" + text + "\"");
    const double number = std::stod(numberText);
    double scale = 1.0;
    for (char step : std::string("KMGT")) {
        if (unit.empty()) break;
        scale *= 1024.0;
        if (std::toupper(static_cast<unsigned char>(unit[0])) == step) break;
    }
    const double bytes = number * scale;
    if (!(bytes >= 1.0) || bytes > 1e18) throwInputError("", option, "size out of range: \"" + text + "\"");
    return std::uint64_t(bytes);
}

DensityPrecision parseDensityPrecision(const std::string& text, const std::string& option) {
    if (text == "8") return DensityPrecision::Bits8;
    if (text == "16") return DensityPrecision::Bits16;
    if (text == "32") return DensityPrecision::Bits32;
    throwInputError("", option, "expected 8, 16 or 32 (bits per sample on the GPU), got \"" + text + "\"");
}

MemoryFit parseMemoryFit(const std::string& text, const std::string& option) {
    if (text == "refuse") return MemoryFit::Refuse;
    if (text == "resolution") return MemoryFit::Resolution;
    if (text == "steps") return MemoryFit::Steps;
    throwInputError("", option, "expected refuse, resolution or steps, got \"" + text + "\"");
}

std::size_t bytesPerDensity(DensityPrecision precision) {
    return std::size_t(precisionBits(precision) / 8);
}

int precisionBits(DensityPrecision precision) {
    switch (precision) {
        case DensityPrecision::Bits8:
            return 8;
        case DensityPrecision::Bits16:
            return 16;
        case DensityPrecision::Bits32:
            return 32;
    }
    return 16;
}

std::vector<std::size_t> selectedSteps(const std::optional<StepSelection>& selection, std::size_t count) {
    std::vector<std::size_t> indices;
    const StepSelection chosen = selection.value_or(StepSelection{});
    const std::size_t end = std::min(count, chosen.end.value_or(count));
    for (std::size_t index = chosen.first; index < end; index += chosen.stride) indices.push_back(index);
    return indices;
}

}  // namespace tstyles
