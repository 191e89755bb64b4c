// The JSON files of a Zarr store, read whole and parsed (their typed access: JsonField).
#include "zarr_json.h"

#include <fstream>
#include <sstream>

#include "tstyles/core/errors.h"
#include "tstyles/core/json_text.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

// Metadata files are small; a larger one is not metadata (and would be read whole).
constexpr std::uint64_t kLargestJsonFile = std::uint64_t(16) << 20;

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

}  // namespace tstyles
