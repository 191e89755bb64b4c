// Typed reads from parsed JSON with errors that say where in the file the problem is.
#include "tstyles/core/json_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tstyles/core/errors.h"

namespace tstyles {

JsonField::JsonField(const std::filesystem::path& file, const nlohmann::json& value, std::string path)
    : file_(&file), value_(&value), path_(std::move(path)) {}

void JsonField::fail(const std::string& problem) const {
    throwInputError(*file_, path_, problem);
}

namespace {
// "a string", "an object", "null": reads as a sentence in "expected a number, found a string".
std::string typeWithArticle(const nlohmann::json& value) {
    const std::string name = value.type_name();
    if (value.is_null()) return name;
    return (name.find_first_of("aeiou") == 0 ? "an " : "a ") + name;
}
}  // namespace

void JsonField::expectType(bool matches, const char* expected) const {
    if (!matches) fail(std::string("expected ") + expected + ", found " + typeWithArticle(*value_));
}

std::string JsonField::childPath(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
}

void JsonField::allowOnlyKeys(std::initializer_list<const char*> keys) const {
    expectType(value_->is_object(), "an object");
    for (const auto& item : value_->items()) {
        // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
        const std::string& key = item.key();
        const bool known =
            std::any_of(keys.begin(), keys.end(), [&key](const char* allowed) { return key == allowed; });
        if (known) continue;
        // Listing the keys that are allowed turns a typo into a one-glance fix.
        std::string allowed;
        for (const char* name : keys) allowed += (allowed.empty() ? "" : ", ") + std::string(name);
        throwInputError(*file_, childPath(key), "unknown key (allowed here: " + allowed + ")");
    }
}

JsonField JsonField::member(const std::string& key) const {
    auto field = optionalMember(key);
    if (!field) throwInputError(*file_, childPath(key), "missing required key");
    return *field;
}

JsonField JsonField::member(const std::string& key, const std::string& whenMissing) const {
    auto field = optionalMember(key);
    if (!field) throwInputError(*file_, childPath(key), whenMissing);
    return *field;
}

std::optional<JsonField> JsonField::optionalMember(const std::string& key) const {
    expectType(value_->is_object(), "an object");
    const auto found = value_->find(key);
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

bool JsonField::boolean() const {
    expectType(value_->is_boolean(), "true or false");
    return value_->get<bool>();
}

double JsonField::finiteNumber() const {
    expectType(value_->is_number(), "a number");
    const double number = value_->get<double>();
    // The parser already rejects 1e999 (JSON has no infinity); this guards documents built in code.
    if (!std::isfinite(number)) fail("must be a finite number");
    return number;
}

int JsonField::integer() const {
    const double number = finiteNumber();
    if (number != std::floor(number)) fail("expected an integer, found " + value_->dump());
    if (number < double(std::numeric_limits<int>::min()) ||
        number > double(std::numeric_limits<int>::max())) {
        fail("integer " + value_->dump() + " is out of range");
    }
    return static_cast<int>(number);
}

glm::dvec3 JsonField::finiteVec3() const {
    if (arraySize() != 3) fail("expected an array of 3 numbers, found " + std::to_string(value_->size()));
    return {element(0).finiteNumber(), element(1).finiteNumber(), element(2).finiteNumber()};
}

}  // namespace tstyles
