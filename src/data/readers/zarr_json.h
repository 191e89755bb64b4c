// Reading the JSON files of a Zarr store (metadata and attributes): bad JSON, a missing or oversized
// file, or a field of the wrong type is an InputError naming the file and the field.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tstyles {

// The file's JSON object; not an object (or not JSON) is an InputError.
nlohmann::json readZarrJson(const std::filesystem::path& file);

// A member that must be there and of the type asked for; `field` names it in messages.
const nlohmann::json& requireMember(const nlohmann::json& object, const std::string& key,
                                    const std::filesystem::path& file, const std::string& field);
std::string requireString(const nlohmann::json& value, const std::filesystem::path& file, const std::string& field);
// A list of whole numbers from `least` to 2^53.
std::vector<std::uint64_t> requireCounts(const nlohmann::json& value, std::uint64_t least,
                                         const std::filesystem::path& file, const std::string& field);
// A list of finite numbers.
std::vector<double> requireNumbers(const nlohmann::json& value, const std::filesystem::path& file, const std::string& field);

}  // namespace tstyles
