// One value inside a parsed JSON document together with its field path (`time_steps[3].grid.dims[1]`,
// `stf.opacity[2].at`) and its file, so that every typed read can fail with a message naming the
// file, the field and the problem. The one typed reader of the scene files, the manifests, the grid
// files, the check suites, the comparison thresholds, the Zarr and OME-Zarr metadata and ParaView's
// .series files; their text is parsed by json_text.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "tstyles/core/interval.h"

namespace tstyles {

class JsonField {
public:
    // `file` and `value` must outlive the field and every field taken from it. `path` is empty for
    // the document itself.
    JsonField(const std::filesystem::path& file, const nlohmann::json& value, std::string path);
    // A temporary file name or document would be gone before the field's first read.
    JsonField(std::filesystem::path&& file, const nlohmann::json& value, std::string path) = delete;
    JsonField(const std::filesystem::path& file, nlohmann::json&& value, std::string path) = delete;

    const std::filesystem::path& file() const { return *file_; }
    const std::string& path() const { return path_; }
    const nlohmann::json& value() const { return *value_; }

    [[noreturn]] void fail(const std::string& problem) const;
    // Fails at a key of this object, whether or not it is there ("compositor.reads: missing; ...").
    [[noreturn]] void failAt(std::string_view key, const std::string& problem) const;

    // Objects. allowOnlyKeys also checks that the value is an object at all; an unknown key is
    // reported with the keys allowed there.
    void allowOnlyKeys(std::initializer_list<std::string_view> keys) const;
    void allowOnlyKeys(std::span<const std::string_view> keys) const;
    JsonField member(std::string_view key) const;  // missing: "missing; this key is required"
    // Missing: fails at the key with `whenMissing` ("missing; every case names its scene file").
    JsonField member(std::string_view key, const std::string& whenMissing) const;
    std::optional<JsonField> optionalMember(std::string_view key) const;

    // Arrays.
    std::size_t arraySize() const;
    JsonField element(std::size_t index) const;

    bool isNull() const { return value_->is_null(); }
    bool isString() const { return value_->is_string(); }
    bool isBoolean() const { return value_->is_boolean(); }
    bool isObject() const { return value_->is_object(); }
    bool isArray() const { return value_->is_array(); }
    // "a string", "an object", "null": reads as a sentence in "expected a number, got a string".
    std::string typeWithArticle() const;

    // Scalars. Numbers must be finite; integers may be written as 64 or 64.0.
    std::string string() const;
    // A string that names a file or folder: also one the system can look up (no NUL, no name longer
    // than the file system allows), so the name fails here, with its key, and not in a later lookup.
    std::string pathName() const;
    bool boolean() const;
    double finiteNumber() const;
    double numberIn(const Interval& allowed) const;
    int integer() const;
    int integerIn(int low, int high) const;
    // An array of any length of finite numbers.
    std::vector<double> finiteNumbers() const;
    // An array of any length of whole numbers from `least` to 2^53 (the largest a double holds exactly).
    std::vector<std::uint64_t> wholeNumbers(std::uint64_t least) const;
    // A fixed-length array of numbers, each checked against `allowed`.
    std::vector<double> numbers(std::size_t count, const Interval& allowed) const;
    glm::dvec3 vec3(const Interval& allowed = anyFinite) const;

    // A name from a fixed set; an unknown name is reported with the list of allowed ones.
    template <typename Enum, typename FromString>
    Enum name(FromString fromString, const std::vector<std::string>& allowedNames) const {
        const std::string text = string();
        if (const std::optional<Enum> parsed = fromString(text)) return *parsed;
        failUnknownName(text, allowedNames);
    }

private:
    void expectType(bool matches, const char* expected) const;
    std::string childPath(std::string_view key) const;
    [[noreturn]] void failUnknownName(const std::string& text, const std::vector<std::string>& allowedNames) const;

    const std::filesystem::path* file_;
    const nlohmann::json* value_;
    std::string path_;
};

}  // namespace tstyles
