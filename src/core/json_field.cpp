// Typed reads from parsed JSON with errors that say where in the file the problem is.
#include "tstyles/core/json_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"

namespace tstyles {
namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

}  // namespace

JsonField::JsonField(const std::filesystem::path& file, const nlohmann::json& value, std::string path)
    : file_(&file), value_(&value), path_(std::move(path)) {}

void JsonField::fail(const std::string& problem) const { throwInputError(*file_, path_, problem); }

void JsonField::failAt(std::string_view key, const std::string& problem) const {
    throwInputError(*file_, childPath(key), problem);
}

std::string JsonField::typeWithArticle() const {
    const std::string name = value_->type_name();
    if (value_->is_null()) return name;
    return (name.find_first_of("aeiou") == 0 ? "an " : "a ") + name;
}

void JsonField::expectType(bool matches, const char* expected) const {
    if (!matches)
        fail(std::string("expected ") + expected + (path_.empty() ? " at the top level" : "") + ", got " +
             typeWithArticle());
}

std::string JsonField::childPath(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void JsonField::allowOnlyKeys(std::initializer_list<std::string_view> keys) const {
    allowOnlyKeys(std::span<const std::string_view>(keys.begin(), keys.size()));
}

void JsonField::allowOnlyKeys(std::span<const std::string_view> keys) const {
    expectType(value_->is_object(), "an object");
    for (const auto& item : value_->items()) {
        // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
        const std::string& key = item.key();
        if (std::any_of(keys.begin(), keys.end(), [&key](std::string_view allowed) { return key == allowed; }))
            continue;
        // Listing the keys that are allowed turns a typo into a one-glance fix.
        const std::vector<std::string> allowed(keys.begin(), keys.end());
        const std::string owner = path_.empty() ? "at the top level" : "in \"" + path_ + "\"";
        failAt(key, "unknown key; the keys allowed " + owner + " are: " + joined(allowed));
    }
}

JsonField JsonField::member(std::string_view key) const { return member(key, "missing; this key is required"); }

JsonField JsonField::member(std::string_view key, const std::string& whenMissing) const {
    auto field = optionalMember(key);
    if (!field) failAt(key, whenMissing);
    return *field;
}

std::optional<JsonField> JsonField::optionalMember(std::string_view key) const {
    expectType(value_->is_object(), "an object");
    const auto found = value_->find(std::string(key));
    if (found == value_->end()) return std::nullopt;
    return JsonField(*file_, *found, childPath(key));
}

std::size_t JsonField::arraySize() const {
    expectType(value_->is_array(), "an array");
    return value_->size();
}

JsonField JsonField::element(std::size_t index) const {
    expectType(value_->is_array(), "an array");
    return JsonField(*file_, value_->at(index), path_ + "[" + std::to_string(index) + "]");
}

std::string JsonField::string() const {
    expectType(value_->is_string(), "a string");
    return value_->get<std::string>();
}

std::string JsonField::pathName() const {
    std::string name = string();
    requireUsablePathName(PathSource{*file_, path_}, name);
    return name;
}

bool JsonField::boolean() const {
    expectType(value_->is_boolean(), "true or false");
    return value_->get<bool>();
}

double JsonField::finiteNumber() const {
    expectType(value_->is_number(), "a number");
    const double number = value_->get<double>();
    // The parser already rejects 1e999 (JSON has no infinity); this guards documents built in code.
    if (!std::isfinite(number)) fail("must be a finite number, got " + formatNumber(number));
    return number;
}

double JsonField::numberIn(const Interval& allowed) const {
    const double number = finiteNumber();
    if (!allowed.contains(number)) fail(allowed.refusal(number));
    return number;
}

int JsonField::integer() const {
    const double number = finiteNumber();
    if (number != std::floor(number)) fail("expected an integer, got " + formatNumber(number));
    if (number < double(std::numeric_limits<int>::min()) || number > double(std::numeric_limits<int>::max()))
        fail("integer " + formatNumber(number) + " is out of range");
    return static_cast<int>(number);
}

int JsonField::integerIn(int low, int high) const {
    const double number = finiteNumber();
    if (number != std::floor(number)) fail("expected an integer, got " + formatNumber(number));
    if (number < low || number > high)
        fail("must be in [" + std::to_string(low) + ", " + std::to_string(high) + "], got " + formatNumber(number));
    return int(number);
}

std::vector<double> JsonField::numbers(std::size_t count, const Interval& allowed) const {
    if (arraySize() != count)
        fail("expected an array of " + std::to_string(count) + " numbers, got " + std::to_string(value_->size()) +
             " elements");
    std::vector<double> result;
    for (std::size_t i = 0; i < count; ++i) result.push_back(element(i).numberIn(allowed));
    return result;
}

std::vector<double> JsonField::finiteNumbers() const {
    std::vector<double> result;
    for (std::size_t i = 0; i < arraySize(); ++i) result.push_back(element(i).finiteNumber());
    return result;
}

std::vector<std::uint64_t> JsonField::wholeNumbers(std::uint64_t least) const {
    constexpr std::uint64_t kLargest = std::uint64_t(1) << 53;
    std::vector<std::uint64_t> result;
    for (std::size_t i = 0; i < arraySize(); ++i) {
        const JsonField item = element(i);
        const double number = item.finiteNumber();
        if (number != std::floor(number) || number < double(least) || number > double(kLargest))
            item.fail("expected a whole number from " + std::to_string(least) + " to 2^53, got " + formatNumber(number));
        result.push_back(std::uint64_t(number));
    }
    return result;
}

glm::dvec3 JsonField::vec3(const Interval& allowed) const {
    const std::vector<double> xyz = numbers(3, allowed);
    return {xyz[0], xyz[1], xyz[2]};
}

void JsonField::failUnknownName(const std::string& text, const std::vector<std::string>& allowedNames) const {
    fail("unknown value \"" + text + "\"; allowed values: " + joined(allowedNames));
}

}  // namespace tstyles
