// Typed access to the JSON of a Zarr store, with the file and field in every message.
#include "zarr_json.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "tstyles/core/errors.h"
#include "tstyles/core/json_text.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

// Metadata files are small; a larger one is not metadata (and would be read whole).
constexpr std::uint64_t kLargestJsonFile = std::uint64_t(16) << 20;

std::string jsonTypeName(const nlohmann::json& value) { return value.type_name(); }

}  // namespace

nlohmann::json readZarrJson(const std::filesystem::path& file) {
    const std::uint64_t size = regularFileSize(file, "Zarr metadata file");
    if (size > kLargestJsonFile)
        throwInputError(file, "", "is " + byteCountText(double(size)) + ", too large for Zarr metadata");
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throwInputError(file, "", "cannot be read");
    const nlohmann::json json = parseJsonText(text.str(), file, JsonComments::Refused);
    if (!json.is_object()) throwInputError(file, "", "is JSON but not an object");
    return json;
}

const nlohmann::json& requireMember(const nlohmann::json& object, const std::string& key,
                                    const std::filesystem::path& file, const std::string& field) {
    if (!object.is_object()) throwInputError(file, field, "must be an object, found " + jsonTypeName(object));
    const auto found = object.find(key);
    if (found == object.end()) throwInputError(file, field.empty() ? key : field + "." + key, "is missing");
    return *found;
}

std::string requireString(const nlohmann::json& value, const std::filesystem::path& file, const std::string& field) {
    if (!value.is_string()) throwInputError(file, field, "must be a string, found " + jsonTypeName(value));
    return value.get<std::string>();
}

std::vector<std::uint64_t> requireCounts(const nlohmann::json& value, std::uint64_t least,
                                         const std::filesystem::path& file, const std::string& field) {
    if (!value.is_array()) throwInputError(file, field, "must be a list of whole numbers, found " + jsonTypeName(value));
    std::vector<std::uint64_t> counts;
    for (const auto& item : value) {
        if (!item.is_number_integer() || (item.is_number_integer() && !item.is_number_unsigned() && item.get<std::int64_t>() < 0))
            throwInputError(file, field, "must hold whole numbers of at least " + std::to_string(least) + ", found " + item.dump());
        const std::uint64_t count = item.get<std::uint64_t>();
        if (count < least || count > (std::uint64_t(1) << 53))
            throwInputError(file, field, "holds " + std::to_string(count) + ", outside " + std::to_string(least) + " to 2^53");
        counts.push_back(count);
    }
    return counts;
}

std::vector<double> requireNumbers(const nlohmann::json& value, const std::filesystem::path& file, const std::string& field) {
    if (!value.is_array()) throwInputError(file, field, "must be a list of numbers, found " + jsonTypeName(value));
    std::vector<double> numbers;
    for (const auto& item : value) {
        if (!item.is_number() || !std::isfinite(item.get<double>()))
            throwInputError(file, field, "must hold finite numbers, found " + item.dump());
        numbers.push_back(item.get<double>());
    }
    return numbers;
}

}  // namespace tstyles
