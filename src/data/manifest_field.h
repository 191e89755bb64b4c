// One value inside a parsed manifest together with its field path (`time_steps[3].grid.dims[1]`),
// so that every typed read can fail with a message naming the file, the field and the problem.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace tstyles {

class ManifestField {
public:
    // `file` and `value` must outlive the field and every field taken from it.
    ManifestField(const std::filesystem::path& file, const nlohmann::json& value, std::string path);

    const std::filesystem::path& file() const { return *file_; }
    const std::string& path() const { return path_; }

    [[noreturn]] void fail(const std::string& problem) const;

    // Objects. allowOnlyKeys also checks that the value is an object at all.
    void allowOnlyKeys(std::initializer_list<const char*> keys) const;
    ManifestField member(const std::string& key) const;  // missing: "missing required key"
    std::optional<ManifestField> optionalMember(const std::string& key) const;

    // Arrays.
    std::size_t arraySize() const;
    ManifestField element(std::size_t index) const;

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

// The most samples one time-step's grid may have (2^36): beyond any GPU's memory, and far from overflow.
inline constexpr std::uint64_t kMaxVoxelsPerStep = std::uint64_t(1) << 36;

// How a grid kind words the errors of its "dims" (the messages name what is counted).
struct GridDimsWording {
    const char* expectedThree;  // e.g. "expected 3 sample counts (x, y, z)"
    const char* whyTwo;         // why each count must be at least 2
    const char* tooMany;        // e.g. "too many voxels for one time-step"
};

// A grid's "dims": three integers, each at least 2, whose product is at most `maxCount`.
glm::ivec3 readGridDims(const ManifestField& dims, std::uint64_t maxCount, const GridDimsWording& wording);

}  // namespace tstyles
