// One value inside a parsed JSON document together with its field path (`time_steps[3].grid.dims[1]`)
// and its file, so that every typed read can fail with a message naming the file, the field and the
// problem. The one typed reader of the manifests, the check suites and the comparison thresholds.
#pragma once

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace tstyles {

class JsonField {
public:
    // `file` and `value` must outlive the field and every field taken from it.
    JsonField(const std::filesystem::path& file, const nlohmann::json& value, std::string path);
    // A temporary file name or document would be gone before the field's first read.
    JsonField(std::filesystem::path&& file, const nlohmann::json& value, std::string path) = delete;
    JsonField(const std::filesystem::path& file, nlohmann::json&& value, std::string path) = delete;

    const std::filesystem::path& file() const { return *file_; }
    const std::string& path() const { return path_; }

    [[noreturn]] void fail(const std::string& problem) const;

    // Objects. allowOnlyKeys also checks that the value is an object at all.
    void allowOnlyKeys(std::initializer_list<const char*> keys) const;
    JsonField member(const std::string& key) const;  // missing: "missing required key"
    // Missing: fails at the key with `whenMissing` ("missing; every case names its scene file").
    JsonField member(const std::string& key, const std::string& whenMissing) const;
    std::optional<JsonField> optionalMember(const std::string& key) const;

    // Arrays.
    std::size_t arraySize() const;
    JsonField element(std::size_t index) const;

    bool isNull() const { return value_->is_null(); }
    bool isString() const { return value_->is_string(); }

    // Scalars. Numbers must be finite; integers may be written as 64 or 64.0.
    std::string string() const;
    bool boolean() const;
    double finiteNumber() const;
    int integer() const;
    // An array of exactly three finite numbers.
    glm::dvec3 finiteVec3() const;

private:
    void expectType(bool matches, const char* expected) const;
    std::string childPath(const std::string& key) const;

    const std::filesystem::path* file_;
    const nlohmann::json* value_;
    std::string path_;
};

}  // namespace tstyles
