// Median cut (Heckbert 1982) over a 15-bit colour histogram: boxes of colours are split at the
// weighted median of their widest channel until there are 256, each box's mean becomes an entry.
#include "gif_palette.h"

#include <algorithm>
#include <unordered_map>

namespace tstyles::video {
namespace {

constexpr std::size_t kEntries = 256;

std::uint32_t packed(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    return 0xFF000000u | (std::uint32_t(r) << 16) | (std::uint32_t(g) << 8) | std::uint32_t(b);
}

// One 5-bit-per-channel cell of the histogram: how many pixels, and the sum of their colours.
struct Cell {
    std::array<int, 3> key{};  // the cell's 5-bit coordinates
    double count = 0.0;
    std::array<double, 3> sum{};
};

struct Box {
    std::vector<Cell*> cells;
    double count = 0.0;
    int widestChannel = 0;
    int width = 0;
};

Box boxOf(std::vector<Cell*> cells) {
    Box box{std::move(cells)};
    std::array<int, 3> low{31, 31, 31};
    std::array<int, 3> high{0, 0, 0};
    for (const Cell* cell : box.cells) {
        box.count += cell->count;
        for (int c = 0; c < 3; ++c) low[c] = std::min(low[c], cell->key[c]), high[c] = std::max(high[c], cell->key[c]);
    }
    for (int c = 0; c < 3; ++c)
        if (high[c] - low[c] > box.width) box.width = high[c] - low[c], box.widestChannel = c;
    return box;
}

std::vector<Box> medianCut(std::vector<Cell>& cells) {
    std::vector<Cell*> all;
    for (Cell& cell : cells) all.push_back(&cell);
    std::vector<Box> boxes{boxOf(std::move(all))};
    while (boxes.size() < kEntries) {
        // The box with the most pixels among those that can still be split.
        auto largest = std::max_element(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) {
            return (a.width > 0 ? a.count : -1.0) < (b.width > 0 ? b.count : -1.0);
        });
        if (largest->width == 0) break;
        Box box = std::move(*largest);
        boxes.erase(largest);
        const int channel = box.widestChannel;
        std::sort(box.cells.begin(), box.cells.end(),
                  [channel](const Cell* a, const Cell* b) { return a->key[channel] < b->key[channel]; });
        double below = 0.0;
        std::size_t split = 1;
        for (; split < box.cells.size(); ++split) {
            below += box.cells[split - 1]->count;
            if (below >= 0.5 * box.count) break;
        }
        split = std::min(split, box.cells.size() - 1);
        boxes.push_back(boxOf({box.cells.begin(), box.cells.begin() + std::ptrdiff_t(split)}));
        boxes.push_back(boxOf({box.cells.begin() + std::ptrdiff_t(split), box.cells.end()}));
    }
    return boxes;
}

PalettedFrame exactPalette(const std::vector<std::uint8_t>& rgb, const std::unordered_map<std::uint32_t, int>& colours) {
    PalettedFrame frame;
    std::unordered_map<std::uint32_t, std::uint8_t> indexOf;
    for (const auto& [colour, count] : colours) {
        const auto index = std::uint8_t(indexOf.size());
        indexOf[colour] = index;
        frame.palette[index] = colour;
    }
    frame.indices.reserve(rgb.size() / 3);
    for (std::size_t i = 0; i < rgb.size(); i += 3)
        frame.indices.push_back(indexOf.at(packed(rgb[i], rgb[i + 1], rgb[i + 2])));
    return frame;
}

}  // namespace

PalettedFrame paletteFrame(const std::vector<std::uint8_t>& rgb, int width, int height) {
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    std::unordered_map<std::uint32_t, int> colours;
    for (std::size_t i = 0; i < pixels * 3 && colours.size() <= kEntries; i += 3)
        ++colours[packed(rgb[i], rgb[i + 1], rgb[i + 2])];
    if (colours.size() <= kEntries) return exactPalette(rgb, colours);

    std::vector<Cell> histogram(32 * 32 * 32);
    const auto cellIndex = [&](std::size_t i) { return (rgb[i] >> 3) << 10 | (rgb[i + 1] >> 3) << 5 | (rgb[i + 2] >> 3); };
    for (std::size_t i = 0; i < pixels * 3; i += 3) {
        Cell& cell = histogram[std::size_t(cellIndex(i))];
        cell.count += 1.0;
        for (int c = 0; c < 3; ++c) cell.sum[std::size_t(c)] += rgb[i + std::size_t(c)];
    }
    std::vector<Cell> used;
    for (std::size_t i = 0; i < histogram.size(); ++i)
        if (histogram[i].count > 0.0) {
            histogram[i].key = {int(i >> 10), int(i >> 5 & 31), int(i & 31)};
            used.push_back(histogram[i]);
        }
    const std::vector<Box> boxes = medianCut(used);

    PalettedFrame frame;
    std::vector<std::array<double, 3>> entries;
    for (const Box& box : boxes) {
        std::array<double, 3> mean{};
        for (const Cell* cell : box.cells)
            for (std::size_t c = 0; c < 3; ++c) mean[c] += cell->sum[c];
        for (double& channel : mean) channel /= box.count;
        frame.palette[entries.size()] = packed(std::uint8_t(mean[0] + 0.5), std::uint8_t(mean[1] + 0.5), std::uint8_t(mean[2] + 0.5));
        entries.push_back(mean);
    }
    // Each cell's nearest entry, found once per cell rather than once per pixel.
    std::vector<std::uint8_t> nearestOfCell(histogram.size(), 0);
    for (const Cell& cell : used) {
        const std::size_t key = std::size_t(cell.key[0] << 10 | cell.key[1] << 5 | cell.key[2]);
        double best = 1e300;
        for (std::size_t e = 0; e < entries.size(); ++e) {
            double distance = 0.0;
            for (std::size_t c = 0; c < 3; ++c) {
                const double d = cell.sum[c] / cell.count - entries[e][c];
                distance += d * d;
            }
            if (distance < best) best = distance, nearestOfCell[key] = std::uint8_t(e);
        }
    }
    frame.indices.reserve(pixels);
    for (std::size_t i = 0; i < pixels * 3; i += 3) frame.indices.push_back(nearestOfCell[std::size_t(cellIndex(i))]);
    return frame;
}

}  // namespace tstyles::video
