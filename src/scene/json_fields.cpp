// Typed, range-checked reads from parsed JSON, with messages that say where and what.
#include "json_fields.h"

#include <charconv>
#include <cmath>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"

namespace tstyles {
namespace {

// "a number", "an object", "null": how a JSON type reads inside "expected ..., got ...".
std::string typeWithArticle(const nlohmann::json& value) {
    const std::string type = value.type_name();
    if (value.is_null()) return type;
    const bool vowel = type.find_first_of("aeiou") == 0;
    return (vowel ? "an " : "a ") + type;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

}  // namespace

std::string childPath(const std::string& parent, std::string_view key) {
    return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

std::string elementPath(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

std::string formatNumber(double value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

bool Interval::contains(double value) const {
    const bool aboveLow = lowIncluded ? value >= low : value > low;
    const bool belowHigh = highIncluded ? value <= high : value < high;
    return aboveLow && belowHigh;
}

std::string Interval::describe() const {
    if (std::isinf(high) && std::isinf(low)) return "finite";
    if (std::isinf(high)) return (lowIncluded ? ">= " : "> ") + formatNumber(low);
    return std::string("in ") + (lowIncluded ? "[" : "(") + formatNumber(low) + ", " + formatNumber(high) +
           (highIncluded ? "]" : ")");
}

void JsonFieldReader::fail(const std::string& path, const std::string& problem) const {
    throwInputError(file_, path, problem);
}

void JsonFieldReader::expectObject(const nlohmann::json& value, const std::string& path,
                                   std::initializer_list<std::string_view> allowed) const {
    if (!value.is_object()) {
        fail(path, std::string("expected an object") + (path.empty() ? " at the top level" : "") + ", got " +
                       typeWithArticle(value));
    }
    for (const auto& [key, child] : value.items()) {
        bool known = false;
        for (std::string_view name : allowed) known = known || key == name;
        if (known) continue;
        const std::vector<std::string> allowedNames(allowed.begin(), allowed.end());
        const std::string owner = path.empty() ? "at the top level" : "in \"" + path + "\"";
        fail(childPath(path, key),
             "unknown key; the keys allowed " + owner + " are: " + joined(allowedNames));
    }
}

void JsonFieldReader::expectArray(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_array()) fail(path, "expected an array, got " + typeWithArticle(value));
}

const nlohmann::json* JsonFieldReader::member(const nlohmann::json& object, std::string_view key) {
    const auto found = object.find(std::string(key));
    return found == object.end() ? nullptr : &*found;
}

const nlohmann::json& JsonFieldReader::requiredMember(const nlohmann::json& object, const std::string& path,
                                                      std::string_view key) const {
    if (const nlohmann::json* found = member(object, key)) return *found;
    fail(childPath(path, key), "missing; this key is required");
}

double JsonFieldReader::finiteNumber(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, "expected a number, got " + typeWithArticle(value));
    const double number = value.get<double>();
    if (!std::isfinite(number)) fail(path, "must be a finite number, got " + formatNumber(number));
    return number;
}

double JsonFieldReader::numberIn(const nlohmann::json& value, const std::string& path,
                                 const Interval& allowed) const {
    const double number = finiteNumber(value, path);
    if (!allowed.contains(number))
        fail(path, "must be " + allowed.describe() + ", got " + formatNumber(number));
    return number;
}

int JsonFieldReader::integerIn(const nlohmann::json& value, const std::string& path, int low,
                               int high) const {
    const double number = finiteNumber(value, path);
    if (std::floor(number) != number) fail(path, "expected an integer, got " + formatNumber(number));
    if (number < low || number > high) {
        fail(path, "must be in [" + std::to_string(low) + ", " + std::to_string(high) + "], got " +
                       formatNumber(number));
    }
    return int(number);
}

std::string JsonFieldReader::string(const nlohmann::json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, "expected a string, got " + typeWithArticle(value));
    return value.get<std::string>();
}

std::string JsonFieldReader::pathName(const nlohmann::json& value, const std::string& path) const {
    std::string name = string(value, path);
    requireUsablePathName(PathSource{file_, path}, name);
    return name;
}

std::vector<double> JsonFieldReader::numbers(const nlohmann::json& value, const std::string& path,
                                             std::size_t count, const Interval& allowed) const {
    expectArray(value, path);
    if (value.size() != count) {
        fail(path, "expected an array of " + std::to_string(count) + " numbers, got " +
                       std::to_string(value.size()) + " elements");
    }
    std::vector<double> result;
    for (std::size_t i = 0; i < count; ++i)
        result.push_back(numberIn(value[i], elementPath(path, i), allowed));
    return result;
}

glm::dvec3 JsonFieldReader::vec3(const nlohmann::json& value, const std::string& path,
                                 const Interval& allowed) const {
    const std::vector<double> xyz = numbers(value, path, 3, allowed);
    return {xyz[0], xyz[1], xyz[2]};
}

void JsonFieldReader::failUnknownName(const std::string& path, const std::string& text,
                                      const std::vector<std::string>& allowedNames) const {
    fail(path, "unknown value \"" + text + "\"; allowed values: " + joined(allowedNames));
}

}  // namespace tstyles
