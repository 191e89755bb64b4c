// Fuzz target: a style image (PNG by name; OpenImageIO falls back to the content for others)
// read as the style library reads it, under the fuzz memory cap.
#include "fuzz_support.h"
#include "tstyles/image/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto file = tstyles_fuzz::writeScratchFile("style.png", tstyles_fuzz::asText(data, size));
    tstyles_fuzz::expectInputErrorAtMost([&] { tstyles::readImage(file, tstyles_fuzz::kMemoryCap); });
    return 0;
}
