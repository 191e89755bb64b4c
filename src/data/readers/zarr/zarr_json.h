// Reading the JSON files of a Zarr store (metadata and attributes): bad JSON, a missing or oversized
// file, or a document that is not an object is an InputError naming the file.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

namespace tstyles {

// The file's JSON object; not an object (or not JSON) is an InputError.
nlohmann::json readZarrJson(const std::filesystem::path& file);

// Typed access to what it holds goes through JsonField (tstyles/core/json_field.h), with the file
// and the field in every message, as for every other JSON the program reads.

}  // namespace tstyles
