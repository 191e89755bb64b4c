// Fuzz target: a scene file's JSON, parsed in memory (the reader never opens the dataset).
#include <string>

#include "fuzz_support.h"
#include "tstyles/scene/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string json(tstyles_fuzz::asText(data, size));
    tstyles_fuzz::expectInputErrorAtMost(
        [&] { tstyles::parseScene(json, tstyles_fuzz::scratchFolder() / "scene.json"); });
    return 0;
}
