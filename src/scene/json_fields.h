// Reads typed, range-checked values out of parsed JSON. Every failure is an InputError that names
// the file, the key as a JSON path ("stf.opacity[2].at") and what was wrong. Private to src/scene.
#pragma once

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace tstyles {

// "image" + "width" -> "image.width"; at the top level (empty parent) just the key.
std::string childPath(const std::string& parent, std::string_view key);
// "stf.opacity" + 2 -> "stf.opacity[2]".
std::string elementPath(const std::string& parent, std::size_t index);

// Shortest text that reads back as the same double ("0.1", "1e+300", "inf").
std::string formatNumber(double value);

// The values a number may take; either end may be open, and `high` may be +infinity.
struct Interval {
    double low;
    double high;
    bool lowIncluded = true;
    bool highIncluded = true;

    bool contains(double value) const;
    // "in [0, 1]", "in (0, 180)", "> 0", ">= 0".
    std::string describe() const;
};

class JsonFieldReader {
public:
    explicit JsonFieldReader(std::filesystem::path file) : file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& problem) const;

    // Checks that `value` is an object holding no key outside `allowed`.
    void expectObject(const nlohmann::json& value, const std::string& path,
                      std::initializer_list<std::string_view> allowed) const;
    void expectArray(const nlohmann::json& value, const std::string& path) const;

    // The member, or null when the object lacks it.
    static const nlohmann::json* member(const nlohmann::json& object, std::string_view key);
    const nlohmann::json& requiredMember(const nlohmann::json& object, const std::string& path,
                                         std::string_view key) const;

    double finiteNumber(const nlohmann::json& value, const std::string& path) const;
    double numberIn(const nlohmann::json& value, const std::string& path, const Interval& allowed) const;
    int integerIn(const nlohmann::json& value, const std::string& path, int low, int high) const;
    std::string string(const nlohmann::json& value, const std::string& path) const;
    // A string that names a file or folder: also one the system can look up (no NUL, no name longer
    // than the file system allows), so the name fails here, with its key, and not in a later lookup.
    std::string pathName(const nlohmann::json& value, const std::string& path) const;
    // A fixed-length array of numbers, each checked against `allowed`.
    std::vector<double> numbers(const nlohmann::json& value, const std::string& path, std::size_t count,
                                const Interval& allowed) const;
    glm::dvec3 vec3(const nlohmann::json& value, const std::string& path, const Interval& allowed) const;

    // A name from a fixed set; an unknown name is reported with the list of allowed ones.
    template <typename Enum, typename FromString>
    Enum name(const nlohmann::json& value, const std::string& path, FromString fromString,
              const std::vector<std::string>& allowedNames) const {
        const std::string text = string(value, path);
        if (const std::optional<Enum> parsed = fromString(text)) return *parsed;
        failUnknownName(path, text, allowedNames);
    }

private:
    [[noreturn]] void failUnknownName(const std::string& path, const std::string& text,
                                      const std::vector<std::string>& allowedNames) const;

    std::filesystem::path file_;
};

// Any finite number (finiteness is checked before the interval).
inline constexpr Interval anyFinite{-std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::infinity()};

}  // namespace tstyles
