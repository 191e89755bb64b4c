// Fuzz target: an OME-Zarr store made of the input. Its first byte picks Zarr v2 or v3 ('3'); the
// rest is three parts split at NUL bytes: the group's attributes (.zattrs, or zarr.json for v3), the
// array metadata of level "0" (.zarray or zarr.json) and one chunk file, stored under the chunk keys
// of 3D and 5D arrays. The store is opened with the fuzz memory cap and every time-step is read.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_support.h"
#include "tstyles/data/read_options.h"
#include "tstyles/data/series_opener.h"

namespace {

std::vector<std::string_view> splitAtNul(std::string_view text, std::size_t parts) {
    std::vector<std::string_view> result;
    while (result.size() + 1 < parts) {
        const auto end = text.find('\0');
        if (end == std::string_view::npos) break;
        result.push_back(text.substr(0, end));
        text.remove_prefix(end + 1);
    }
    result.push_back(text);
    result.resize(parts);
    return result;
}

void writeFile(const std::filesystem::path& file, std::string_view bytes) {
    std::filesystem::create_directories(file.parent_path());
    tstyles_fuzz::writeScratchFile(std::filesystem::relative(file, tstyles_fuzz::scratchFolder()).string(), bytes);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input = tstyles_fuzz::asText(data, size);
    const bool v3 = !input.empty() && input.front() == '3';
    const auto parts = splitAtNul(input.empty() ? input : input.substr(1), 3);
    const std::filesystem::path store = tstyles_fuzz::scratchFolder() / "input.zarr";
    std::filesystem::remove_all(store);
    if (v3) {
        writeFile(store / "zarr.json", parts[0]);
        writeFile(store / "0" / "zarr.json", parts[1]);
        for (const char* key : {"c/0/0/0", "0.0.0.0.0"}) writeFile(store / "0" / key, parts[2]);
    } else {
        writeFile(store / ".zgroup", R"({"zarr_format": 2})");
        writeFile(store / ".zattrs", parts[0]);
        writeFile(store / "0" / ".zarray", parts[1]);
        for (const char* key : {"0.0.0", "0.0.0.0.0", "0/0/0"}) writeFile(store / "0" / key, parts[2]);
    }
    tstyles::ReadOptions options;
    options.maxMemoryBytes = tstyles_fuzz::kMemoryCap;
    tstyles_fuzz::expectInputErrorAtMost([&] { tstyles::openSeries(store, options); });
    return 0;
}
