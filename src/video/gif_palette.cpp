// Median cut: the frame's colours, weighted by how many pixels use them, are split at the weighted
// median of the widest channel of the widest box until there are 256 boxes; each box's mean is a
// palette entry.
#include "gif_palette.h"

#include <algorithm>
#include <cassert>
#include <unordered_map>

namespace tstyles::video {

namespace {

using Rgb = std::array<int, 3>;

struct ColourCount {
    Rgb rgb;
    std::uint64_t count;
};

std::uint32_t packedKey(const Rgb& c) { return std::uint32_t(c[0] << 16 | c[1] << 8 | c[2]); }
std::uint32_t paletteEntry(const Rgb& c) { return 0xFF000000u | packedKey(c); }

std::vector<ColourCount> histogram(std::span<const std::uint8_t> rgb) {
    std::unordered_map<std::uint32_t, std::uint64_t> counts;
    for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) ++counts[packedKey({rgb[i], rgb[i + 1], rgb[i + 2]})];
    std::vector<ColourCount> colours;
    colours.reserve(counts.size());
    for (const auto& [key, count] : counts)
        colours.push_back({{int(key >> 16 & 0xFF), int(key >> 8 & 0xFF), int(key & 0xFF)}, count});
    // Sorted, so the palette does not depend on the hash map's order.
    std::sort(colours.begin(), colours.end(),
              [](const ColourCount& a, const ColourCount& b) { return packedKey(a.rgb) < packedKey(b.rgb); });
    return colours;
}

struct Box {
    std::size_t begin, end;  // a range of the colour list
    int widestChannel = 0;
    int extent = 0;
};

Box measured(const std::vector<ColourCount>& colours, std::size_t begin, std::size_t end) {
    Box box{begin, end};
    for (int channel = 0; channel < 3; ++channel) {
        int low = 255, high = 0;
        for (std::size_t i = begin; i < end; ++i) {
            low = std::min(low, colours[i].rgb[channel]);
            high = std::max(high, colours[i].rgb[channel]);
        }
        if (high - low > box.extent) box = {begin, end, channel, high - low};
    }
    return box;
}

std::vector<Rgb> medianCut(std::vector<ColourCount>& colours, std::size_t paletteSize) {
    std::vector<Box> boxes{measured(colours, 0, colours.size())};
    while (boxes.size() < paletteSize) {
        auto widest = std::max_element(boxes.begin(), boxes.end(),
                                       [](const Box& a, const Box& b) { return a.extent < b.extent; });
        if (widest->extent == 0) break;  // every box is one colour
        const Box box = *widest;
        const int channel = box.widestChannel;
        std::sort(colours.begin() + std::ptrdiff_t(box.begin), colours.begin() + std::ptrdiff_t(box.end),
                  [channel](const ColourCount& a, const ColourCount& b) { return a.rgb[channel] < b.rgb[channel]; });
        std::uint64_t total = 0;
        for (std::size_t i = box.begin; i < box.end; ++i) total += colours[i].count;
        // The weighted median, kept off the ends so both halves hold a colour.
        std::size_t split = box.begin + 1;
        for (std::uint64_t below = colours[box.begin].count; split < box.end - 1 && 2 * below < total; ++split)
            below += colours[split].count;
        *widest = measured(colours, box.begin, split);
        boxes.push_back(measured(colours, split, box.end));
    }
    std::vector<Rgb> palette;
    for (const Box& box : boxes) {
        std::array<std::uint64_t, 3> sum{};
        std::uint64_t count = 0;
        for (std::size_t i = box.begin; i < box.end; ++i) {
            for (int c = 0; c < 3; ++c) sum[std::size_t(c)] += std::uint64_t(colours[i].rgb[c]) * colours[i].count;
            count += colours[i].count;
        }
        Rgb mean;
        for (int c = 0; c < 3; ++c) mean[c] = int((sum[std::size_t(c)] + count / 2) / count);
        palette.push_back(mean);
    }
    return palette;
}

// Nearest palette entry by squared RGB distance, remembered per colour: dithered frames reuse
// colours often, and 256 comparisons per pixel add up on a 512x512 frame.
class NearestEntry {
public:
    explicit NearestEntry(const std::vector<Rgb>& palette) : palette_(palette) {}
    std::uint8_t operator()(const Rgb& c) {
        const auto [it, inserted] = cache_.try_emplace(packedKey(c), std::uint8_t(0));
        if (!inserted) return it->second;
        int best = 0, bestDistance = 1 << 30;
        for (std::size_t i = 0; i < palette_.size(); ++i) {
            int distance = 0;
            for (int k = 0; k < 3; ++k) distance += (c[k] - palette_[i][k]) * (c[k] - palette_[i][k]);
            if (distance < bestDistance) bestDistance = distance, best = int(i);
        }
        return it->second = std::uint8_t(best);
    }

private:
    const std::vector<Rgb>& palette_;
    std::unordered_map<std::uint32_t, std::uint8_t> cache_;
};

constexpr int kMaxCarriedError = 24;

// Floyd-Steinberg: each pixel's rounding error goes 7/16 right, 3/16, 5/16, 1/16 to the row below.
void ditherInto(PalettedFrame& out, std::span<const std::uint8_t> rgb, int width, int height,
                const std::vector<Rgb>& palette) {
    NearestEntry nearest(palette);
    // Errors in 1/16 units, with a pixel of margin on each side.
    std::vector<Rgb> current(std::size_t(width) + 2, Rgb{}), next(std::size_t(width) + 2, Rgb{});
    for (int y = 0; y < height; ++y) {
        std::fill(next.begin(), next.end(), Rgb{});
        for (int x = 0; x < width; ++x) {
            const std::size_t pixel = std::size_t(y) * std::size_t(width) + std::size_t(x);
            Rgb wanted;
            for (int c = 0; c < 3; ++c)
                wanted[c] = std::clamp(int(rgb[pixel * 3 + std::size_t(c)]) + current[std::size_t(x) + 1][c] / 16, 0, 255);
            const std::uint8_t index = nearest(wanted);
            out.indices[pixel] = index;
            for (int c = 0; c < 3; ++c) {
                // Capped, so that where the palette lacks a colour altogether (a corner of the
                // colour cube) the error does not pile up into streaks along the row.
                const int error = std::clamp(wanted[c] - palette[index][c], -kMaxCarriedError, kMaxCarriedError);
                current[std::size_t(x) + 2][c] += error * 7;
                next[std::size_t(x)][c] += error * 3;
                next[std::size_t(x) + 1][c] += error * 5;
                next[std::size_t(x) + 2][c] += error;
            }
        }
        std::swap(current, next);
    }
}

}  // namespace

PalettedFrame palettize(std::span<const std::uint8_t> rgb, int width, int height) {
    assert(rgb.size() == std::size_t(width) * std::size_t(height) * 3);
    PalettedFrame out;
    out.palette.fill(0xFF000000u);
    out.indices.resize(std::size_t(width) * std::size_t(height));
    std::vector<ColourCount> colours = histogram(rgb);

    if (colours.size() <= out.palette.size()) {
        // Few enough colours to keep every one exactly: no dithering needed.
        std::unordered_map<std::uint32_t, std::uint8_t> indexOf;
        for (std::size_t i = 0; i < colours.size(); ++i) {
            out.palette[i] = paletteEntry(colours[i].rgb);
            indexOf[packedKey(colours[i].rgb)] = std::uint8_t(i);
        }
        for (std::size_t p = 0; p < out.indices.size(); ++p)
            out.indices[p] = indexOf.at(packedKey({rgb[3 * p], rgb[3 * p + 1], rgb[3 * p + 2]}));
        return out;
    }

    const std::vector<Rgb> palette = medianCut(colours, out.palette.size());
    for (std::size_t i = 0; i < palette.size(); ++i) out.palette[i] = paletteEntry(palette[i]);
    ditherInto(out, rgb, width, height, palette);
    return out;
}

}  // namespace tstyles::video
