// Fuzz target: a tstyles manifest (series.json) and the raw files it names. The input is the
// manifest; beside it lie small files it may name (values.raw: 4 x 4 x 4 float32, mask.raw:
// 4 x 4 x 4 bytes, values8.raw: 2 x 2 x 2 float32, coords.f32: the 2 x 2 x 2 nodes of a unit
// cube), so that the loader gets past the manifest into its files.
#include <string>

#include "fuzz_support.h"
#include "tstyles/data/manifest.h"

namespace {

// x fastest, three little-endian float32 a node.
std::string unitCubeNodes() {
    std::string bytes;
    for (int node = 0; node < 8; ++node)
        for (int axis = 0; axis < 3; ++axis) {
            const float coordinate = float((node >> axis) & 1);
            bytes.append(reinterpret_cast<const char*>(&coordinate), sizeof coordinate);
        }
    return bytes;
}

void writeValueFiles() {
    static const bool written = [] {
        tstyles_fuzz::writeScratchFile("values.raw", std::string(4 * 4 * 4 * 4, '\x3f'));
        tstyles_fuzz::writeScratchFile("mask.raw", std::string(4 * 4 * 4, '\x01'));
        tstyles_fuzz::writeScratchFile("values8.raw", std::string(2 * 2 * 2 * 4, '\x3f'));
        tstyles_fuzz::writeScratchFile("coords.f32", unitCubeNodes());
        return true;
    }();
    (void)written;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    writeValueFiles();
    const auto manifest = tstyles_fuzz::writeScratchFile("series.json", tstyles_fuzz::asText(data, size));
    tstyles_fuzz::expectInputErrorAtMost([&] { tstyles::loadSeries(manifest, {tstyles_fuzz::kMemoryCap, 2}); });
    return 0;
}
