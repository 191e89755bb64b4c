// What every TIFF reading shares: the channel choice, unit spellings, the checks on a volume's pages.
#include "tiff_layout.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "tstyles/core/ascii_case.h"
#include "tstyles/core/errors.h"

namespace tstyles {

ChannelChoice chooseChannel(const ReadOptions& options, std::size_t planeChannels, std::size_t samples,
                            const std::filesystem::path& file, std::vector<std::string>& notes) {
    const std::size_t channels = planeChannels * samples;
    const int asked = options.channel.value_or(0);
    if (asked < 0 || std::size_t(asked) >= channels)
        throwInputError(file, "--channel",
                        std::to_string(asked) + " is out of range: the image has " + std::to_string(channels) +
                            " channel" + (channels == 1 ? "" : "s") + " (0 to " + std::to_string(channels - 1) + ")");
    if (channels > 1)
        notes.push_back("channel " + std::to_string(asked) + " of " + std::to_string(channels) +
                        (options.channel ? " (--channel)" : " (the first; --channel N takes another)"));
    return {std::size_t(asked) / samples, int(std::size_t(asked) % samples)};
}

std::string normalizedLengthUnit(const std::string& unit) {
    const std::string lower = asciiLowercase(unit);
    if (lower == "micron" || lower == "microns" || lower == "um" || lower == "\\u00b5m" || lower == "µm" ||
        lower == "μm" || lower == "micrometer" || lower == "micrometre")
        return "um";
    if (lower == "pixel" || lower == "pixels" || lower == "none") return "";
    if (lower == "nanometer" || lower == "nanometre") return "nm";
    if (lower == "millimeter" || lower == "millimetre") return "mm";
    if (lower == "centimeter" || lower == "centimetre") return "cm";
    if (lower == "meter" || lower == "metre") return "m";
    if (lower == "kilometer" || lower == "kilometre") return "km";
    if (lower == "å" || lower == "angstrom") return "A";
    return unit;
}

std::optional<double> micrometresPer(const std::string& unit) {
    static const std::map<std::string, double> lengths = {{"um", 1.0},    {"nm", 1e-3}, {"pm", 1e-6},
                                                          {"A", 1e-4},    {"mm", 1e3},  {"cm", 1e4},
                                                          {"dm", 1e5},    {"m", 1e6},   {"km", 1e9},
                                                          {"inch", 25400.0}};
    const auto found = lengths.find(unit);
    if (found == lengths.end()) return std::nullopt;
    return found->second;
}

TimeUnit timeUnitFromText(const std::string& unit) {
    const std::string lower = asciiLowercase(unit);
    if (lower == "s" || lower == "sec" || lower == "second" || lower == "seconds") return TimeUnit::Seconds;
    if (lower == "ms" || lower == "msec" || lower == "millisecond" || lower == "milliseconds") return TimeUnit::Milliseconds;
    if (lower == "µs" || lower == "us" || lower == "\\u00b5s" || lower == "microsecond" || lower == "microseconds")
        return TimeUnit::Microseconds;
    if (lower == "min" || lower == "minute" || lower == "minutes") return TimeUnit::Minutes;
    if (lower == "h" || lower == "hr" || lower == "hour" || lower == "hours") return TimeUnit::Hours;
    if (lower == "d" || lower == "day" || lower == "days") return TimeUnit::Days;
    return TimeUnit::None;
}

void requireSameLayout(const TiffLayout& layout) {
    const TiffPage& first = layout.firstPage();
    if (layout.contiguousOffset != 0) return;  // one page describes every image of the run
    for (const TiffPlaneRef& plane : layout.planes) {
        const TiffPage& page = layout.pages[plane.file][plane.page];
        if (!page.sameLayout(first))
            throwInputError(layout.files[plane.file], "page " + std::to_string(plane.page),
                            "is " + std::to_string(page.width) + " x " + std::to_string(page.height) + " " +
                                page.sampleTypeName() + " with " + std::to_string(page.samplesPerPixel) +
                                " sample(s) per pixel, unlike the volume's first page (" + std::to_string(first.width) +
                                " x " + std::to_string(first.height) + " " + first.sampleTypeName() + " with " +
                                std::to_string(first.samplesPerPixel) + "): the pages of a volume must agree");
    }
}

void requireVolumeShape(const TiffLayout& layout, const std::filesystem::path& file, const std::string& field) {
    const TiffPage& first = layout.firstPage();
    constexpr std::uint32_t kLargest = 1u << 30;  // past int, the grid's type, long before any memory
    if (first.width > kLargest || first.height > kLargest || layout.slices > kLargest)
        throwInputError(file, field, "gives more than 2^30 samples along an axis");
    if (first.width < 2 || first.height < 2 || layout.slices < 2)
        throwInputError(file, field,
                        "gives " + std::to_string(first.width) + " x " + std::to_string(first.height) + " x " +
                            std::to_string(layout.slices) +
                            " samples per time-step: a volume needs at least 2 along x, y and z (slices)");
}

}  // namespace tstyles
