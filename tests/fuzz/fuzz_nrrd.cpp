// Fuzz target: a NRRD header and its data. An input that starts like a detached header (.nhdr)
// may name the small data file lying beside it (volume.raw: the bytes 0 to 255).
#include <string>

#include "fuzz_series_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const bool written = [] {
        std::string bytes(256, '\0');
        for (std::size_t index = 0; index < bytes.size(); ++index) bytes[index] = char(index);
        tstyles_fuzz::writeScratchFile("volume.raw", bytes);
        return true;
    }();
    (void)written;
    const std::string_view text = tstyles_fuzz::asText(data, size);
    const bool detached = text.find("data file:") != std::string_view::npos ||
                          text.find("datafile:") != std::string_view::npos;
    tstyles_fuzz::openSeriesFile(detached ? "input.nhdr" : "input.nrrd", text);
    return 0;
}
