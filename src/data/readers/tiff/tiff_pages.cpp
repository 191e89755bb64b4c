// How many pages make a volume and in which order they come, for TIFFs that do not say it.
#include "tiff_pages.h"

#include <algorithm>
#include <cctype>

#include "../series_assembly.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

// Time slowest (TZYX) unless --axes ZTYX says that the pages run through time first.
bool timeSlowest(const ReadOptions& options, const std::filesystem::path& file) {
    std::string axes;
    for (char c : options.pageAxes) axes += char(std::toupper(static_cast<unsigned char>(c)));
    if (axes.empty() || axes == "TZYX") return true;
    if (axes == "ZTYX") return false;
    throwInputError(file, "--axes",
                    "\"" + options.pageAxes + "\" is not a page order of a volume over time: give TZYX (time slowest) or ZTYX");
}

// x and y from the resolution tags in micrometres (inch or centimetre) or as given (no unit); z
// from ImageJ's spacing= or else as x.
void setPageSpacing(const TiffPage& page, const ImageJDescription* imagej, TiffLayout& layout) {
    const glm::dvec2 xy = spacingFromResolution(page);
    const bool resolved = page.xResolution > 0.0;
    double scale = 1.0;
    if (imagej) {
        layout.unit = normalizedLengthUnit(imagej->unit);
    } else if (resolved && (page.resolutionUnit == 2 || page.resolutionUnit == 3)) {
        scale = page.resolutionUnit == 2 ? 25400.0 : 10000.0;
        layout.unit = "um";
    }
    layout.spacing = {xy.x * scale, xy.y * scale, xy.x * scale};
    if (imagej && imagej->spacing) layout.spacing.z = *imagej->spacing;
    else layout.notes.push_back("the file gives no z spacing: taken as the x spacing");
}

// --dims' NZ (checked against the pages), one file's pages when there are several multi-page files,
// else every page.
std::size_t slicesPerVolume(const std::vector<std::filesystem::path>& files,
                            const std::vector<std::vector<TiffPage>>& pages, std::size_t total,
                            const ReadOptions& options) {
    const std::filesystem::path& file = files.front();
    if (!options.pageAxes.empty() && !options.rawDims)
        throwInputError(file, "--axes", "needs --dims NXxNYxNZ: how many pages (slices) make one volume");
    if (options.rawDims) {
        const glm::ivec3 dims = *options.rawDims;
        const TiffPage& page = pages.front().front();
        if (std::uint32_t(dims.x) != page.width || std::uint32_t(dims.y) != page.height)
            throwInputError(file, "--dims",
                            "gives " + std::to_string(dims.x) + " x " + std::to_string(dims.y) + " samples a slice, the pages are " +
                                std::to_string(page.width) + " x " + std::to_string(page.height));
        if (dims.z < 1 || total % std::size_t(dims.z) != 0)
            throwInputError(file, "--dims",
                            std::to_string(dims.z) + " slices a volume do not divide the " + std::to_string(total) + " pages");
        return std::size_t(dims.z);
    }
    const bool multiPageFiles =
        std::any_of(pages.begin(), pages.end(), [](const auto& filePages) { return filePages.size() > 1; });
    if (files.size() == 1 || !multiPageFiles) return total;
    for (std::size_t index = 0; index < files.size(); ++index)
        if (pages[index].size() != pages.front().size())
            throwInputError(files[index], "",
                            "has " + std::to_string(pages[index].size()) + " pages, " + files.front().filename().string() +
                                " has " + std::to_string(pages.front().size()) +
                                ": a list of multi-page TIFFs is one volume per file, all of one size");
    return pages.front().size();
}

}  // namespace

TiffLayout pageLayout(const std::vector<std::filesystem::path>& files, std::vector<std::vector<TiffPage>> pages,
                      const ImageJDescription* imagej, const ReadOptions& options) {
    const std::filesystem::path& file = files.front();
    std::size_t total = 0;
    for (const auto& filePages : pages) total += filePages.size();
    TiffLayout layout;
    layout.format = files.size() > 1 ? "TIFF (" + std::to_string(files.size()) + " files)" : "TIFF";
    layout.files = files;
    const bool slowTime = timeSlowest(options, file);
    layout.slices = slicesPerVolume(files, pages, total, options);
    layout.steps = total / layout.slices;
    requireStepCount(file, "--dims", layout.steps);
    for (std::size_t t = 0; t < layout.steps; ++t)
        for (std::size_t z = 0; z < layout.slices; ++z) {
            std::size_t index = slowTime ? t * layout.slices + z : z * layout.steps + t;
            std::size_t owner = 0;
            while (index >= pages[owner].size()) index -= pages[owner++].size();
            layout.planes.push_back({owner, index});
        }
    layout.pages = std::move(pages);
    requireVolumeShape(layout, file, options.rawDims ? "--dims" : "pages");
    requireSameLayout(layout);
    const ChannelChoice channel = chooseChannel(options, 1, layout.firstPage().samplesPerPixel, file, layout.notes);
    layout.sample = channel.sample;
    setPageSpacing(layout.firstPage(), imagej, layout);
    for (std::size_t t = 0; t < layout.steps; ++t) layout.times.push_back(double(t));
    if (layout.steps == 1 && total > 1)
        layout.notes.push_back(std::to_string(total) +
                               " pages read as one volume (every page a z-slice); --dims NXxNYxNZ and --axes TZYX or ZTYX "
                               "read them as a time series");
    else
        layout.notes.push_back(std::to_string(total) + " pages as " + std::to_string(layout.steps) + " time-steps of " +
                               std::to_string(layout.slices) + " slices, " + (slowTime ? "time slowest (TZYX)" : "z slowest (ZTYX)") +
                               "; time-steps numbered 0, 1, 2, ...");
    return layout;
}

}  // namespace tstyles
