// From parsed OME-XML and the file's pages to the planes of one channel over time, with physical
// sizes in one length unit and times from the Planes' DeltaT or the Pixels' TimeIncrement.
#include "tiff_ome.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <set>
#include <utility>

#include "../series_assembly.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

std::size_t chooseImage(const std::vector<OmeImage>& images, const std::filesystem::path& file) {
    for (std::size_t index = 0; index < images.size(); ++index)
        if (images[index].sizeZ >= 2 && images[index].sizeT >= 2) return index;
    for (std::size_t index = 0; index < images.size(); ++index)
        if (images[index].sizeZ >= 2) return index;
    throwInputError(file, "OME-XML Pixels SizeZ",
                    "is 1 in every Image: planes over time without a Z axis are not a volume over time");
}

// The physical sizes in the x size's unit where both units are lengths we know.
void setOmeSpacing(const OmeImage& image, TiffLayout& layout) {
    const std::string unitX = normalizedLengthUnit(image.physicalSizeXUnit);
    const auto inUnitX = [&](const std::optional<double>& size, const std::string& unit) {
        if (!size) return 1.0;
        const auto from = micrometresPer(normalizedLengthUnit(unit)), to = micrometresPer(unitX);
        return from && to ? *size * *from / *to : *size;
    };
    layout.spacing = {image.physicalSizeX.value_or(1.0), inUnitX(image.physicalSizeY, image.physicalSizeYUnit),
                      inUnitX(image.physicalSizeZ, image.physicalSizeZUnit)};
    layout.unit = image.physicalSizeX ? unitX : "";
    if (!image.physicalSizeX || !image.physicalSizeZ)
        layout.notes.push_back("no PhysicalSizeX or PhysicalSizeZ: spacing 1 along the axes without one");
}

// DeltaT of plane (0, channel, t) for every t when all are given and increase; else TimeIncrement.
void setOmeTimes(const OmeImage& image, std::size_t planeChannel, TiffLayout& layout) {
    std::vector<std::optional<double>> deltas(image.sizeT);
    std::string unit;
    for (const OmePlane& plane : image.planes)
        if (plane.theZ == 0 && plane.theC == planeChannel && plane.theT < image.sizeT && plane.deltaT) {
            deltas[plane.theT] = plane.deltaT;
            unit = plane.deltaTUnit;
        }
    bool increasing = std::all_of(deltas.begin(), deltas.end(), [](const auto& delta) { return delta.has_value(); });
    for (std::size_t t = 1; increasing && t < deltas.size(); ++t) increasing = *deltas[t] > *deltas[t - 1];
    if (increasing && image.sizeT > 1 && timeUnitFromText(unit) != TimeUnit::None) {
        for (const auto& delta : deltas) layout.times.push_back(*delta);
        layout.time.unit = timeUnitFromText(unit);
        layout.notes.push_back("times from the Planes' DeltaT (" + unit + ")");
        return;
    }
    const TimeUnit incrementUnit = timeUnitFromText(image.timeIncrementUnit);
    const bool timed = image.timeIncrement && incrementUnit != TimeUnit::None;
    for (std::size_t t = 0; t < image.sizeT; ++t) layout.times.push_back(timed ? double(t) * *image.timeIncrement : double(t));
    layout.time.unit = timed ? incrementUnit : TimeUnit::None;
    layout.notes.push_back(timed ? "times from TimeIncrement (" + image.timeIncrementUnit + ")"
                                 : std::string("no DeltaT or TimeIncrement: time-steps are numbered 0, 1, 2, ..."));
}

// A pyramid's level (SubIFDs of every plane, finest first): --level, else the full resolution.
// The chosen planes' pages become that level's, and x and y spacing grow by the downsampling.
void chooseLevel(const ReadOptions& options, std::vector<TiffFile*> files, TiffLayout& layout,
                 const std::filesystem::path& file) {
    std::size_t levels = std::numeric_limits<std::size_t>::max();
    for (const TiffPlaneRef& plane : layout.planes)
        levels = std::min(levels, 1 + layout.pages[plane.file][plane.page].subIfds.size());
    if (options.level && std::size_t(*options.level) >= levels)
        throwInputError(file, "--level",
                        "is " + std::to_string(*options.level) + ": this OME-TIFF has " + std::to_string(levels) +
                            (levels == 1 ? " resolution level (0: no SubIFDs)"
                                         : " resolution levels (0 to " + std::to_string(levels - 1) +
                                               ", in its planes' SubIFDs)"));
    const std::size_t level = std::size_t(options.level.value_or(0));
    const TiffPage full = layout.firstPage();
    if (level > 0) {
        std::set<std::pair<std::size_t, std::size_t>> done;
        for (const TiffPlaneRef& plane : layout.planes)
            if (done.insert({plane.file, plane.page}).second) {
                TiffPage& page = layout.pages[plane.file][plane.page];
                page = files[plane.file]->readSubPage(page, level, plane.page);
            }
        const TiffPage& reduced = layout.firstPage();
        layout.spacing.x *= double(full.width) / double(reduced.width);
        layout.spacing.y *= double(full.height) / double(reduced.height);
    }
    if (levels > 1)
        layout.notes.push_back("resolution level " + std::to_string(level) + " of " + std::to_string(levels) +
                               " (SubIFDs): " + std::to_string(layout.firstPage().width) + " x " +
                               std::to_string(layout.firstPage().height) + " pixels a plane" +
                               (options.level ? " (--level)" : " (the full resolution; --level chooses another)"));
}

}  // namespace

TiffLayout omeLayout(TiffFile& tiff, std::vector<TiffPage> pages, const std::vector<OmeImage>& images,
                     const ReadOptions& options, std::uint64_t cap) {
    const std::filesystem::path& file = tiff.path();
    const std::size_t chosen = chooseImage(images, file);
    const OmeImage& image = images[chosen];
    // An Image without TiffData starts after the planes of the Images before it.
    std::size_t firstIfd = 0;
    for (std::size_t index = 0; index < chosen; ++index)
        firstIfd += images[index].sizeZ * images[index].sizeT * std::max<std::size_t>(1, images[index].sizeC / images[index].samplesPerPixel);
    // The planes may lie in other files beside this one (one per time point, say): their pages too.
    const std::vector<std::string> names = omeFileNames(image, file);
    TiffLayout layout;
    layout.format = "OME-TIFF";
    layout.files = {file};
    layout.pages = {std::move(pages)};
    std::vector<std::unique_ptr<TiffFile>> otherFiles;
    for (std::size_t index = 1; index < names.size(); ++index) {
        const std::filesystem::path other = file.parent_path() / names[index];
        std::error_code error;
        if (!std::filesystem::is_regular_file(other, error))
            throwInputError(file, "OME-XML TiffData UUID FileName",
                            "puts planes in \"" + names[index] + "\", which is not beside this file");
        otherFiles.push_back(std::make_unique<TiffFile>(other, cap));
        layout.files.push_back(other);
        layout.pages.push_back(otherFiles.back()->readPages());
    }
    std::vector<std::size_t> ifdCounts;
    for (const auto& filePages : layout.pages) ifdCounts.push_back(filePages.size());
    const std::vector<OmePlaneRef> refs = omePlaneRefs(image, ifdCounts, firstIfd, file);
    requireStepCount(file, "OME-XML Pixels SizeT", image.sizeT);
    if (names.size() > 1)
        layout.notes.push_back("planes in " + std::to_string(names.size()) + " files named by the OME-XML's TiffData");

    if (images.size() > 1)
        layout.notes.push_back("Image " + std::to_string(chosen) + " of " + std::to_string(images.size()) + " (ID \"" +
                               image.id + "\", \"" + image.name + "\"): the first that is a volume over time");
    const TiffPage& firstPage = layout.pages[refs.front().file][refs.front().ifd];
    if (firstPage.samplesPerPixel != image.samplesPerPixel)
        throwInputError(file, "OME-XML Channel SamplesPerPixel",
                        "is " + std::to_string(image.samplesPerPixel) + ", the TIFF pages have " +
                            std::to_string(firstPage.samplesPerPixel));
    if (firstPage.width != image.sizeX || firstPage.height != image.sizeY)
        throwInputError(file, "OME-XML Pixels SizeX",
                        "SizeX x SizeY = " + std::to_string(image.sizeX) + " x " + std::to_string(image.sizeY) +
                            ", the page (IFD " + std::to_string(refs.front().ifd) + ") is " + std::to_string(firstPage.width) +
                            " x " + std::to_string(firstPage.height));
    const ChannelChoice channel =
        chooseChannel(options, image.sizeC / image.samplesPerPixel, image.samplesPerPixel, file, layout.notes);
    layout.sample = channel.sample;
    layout.slices = image.sizeZ;
    layout.steps = image.sizeT;
    for (std::size_t t = 0; t < image.sizeT; ++t)
        for (std::size_t z = 0; z < image.sizeZ; ++z) {
            const OmePlaneRef& ref = refs[omePlaneIndex(image, z, channel.planeChannel, t)];
            layout.planes.push_back({ref.file, ref.ifd});
        }
    requireVolumeShape(layout, file, "OME-XML Pixels SizeZ");
    requireSameLayout(layout);
    layout.notes.push_back("OME-XML: " + std::to_string(image.sizeZ) + " z x " + std::to_string(image.sizeC) + " c x " +
                           std::to_string(image.sizeT) + " t, DimensionOrder " + image.dimensionOrder);
    setOmeSpacing(image, layout);
    setOmeTimes(image, channel.planeChannel, layout);
    std::vector<TiffFile*> files{&tiff};
    for (const auto& other : otherFiles) files.push_back(other.get());
    chooseLevel(options, files, layout, file);
    // A level's pages are checked as the full ones were: every plane the size and type of the first.
    requireVolumeShape(layout, file, "--level");
    requireSameLayout(layout);
    return layout;
}

}  // namespace tstyles
