// Which TIFF reading applies (OME-XML, ImageJ, plain pages), then one SourceSeries whose time-steps
// are read a plane at a time. Image rows run top-down: the placement turns y (and z, to stay
// right-handed) around so that row 0 is at the top of the picture, as Fiji shows it.
#include "tiff_reader.h"

#include <algorithm>
#include <map>
#include <memory>

#include "../file_magic.h"
#include "../infinite_values.h"
#include "tiff_imagej.h"
#include "tiff_ome.h"
#include "tiff_pages.h"
#include "tstyles/core/ascii_case.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/natural_order.h"

namespace tstyles {
namespace {

bool isTiffName(const std::filesystem::path& file) {
    const std::string extension = lowercaseExtension(file);
    return (extension == ".tif" || extension == ".tiff") && file.filename().string().front() != '.';
}

std::vector<std::filesystem::path> folderFiles(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (isTiffName(entry.path()) && entry.is_regular_file(error)) files.push_back(entry.path());
    if (files.empty()) throwInputError(folder, "", "holds no .tif or .tiff files");
    std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
        return naturalLess(a.filename().string(), b.filename().string());
    });
    return files;
}

void refusePageOptions(const std::filesystem::path& file, const ReadOptions& options, const std::string& format) {
    if (options.rawDims || !options.pageAxes.empty())
        throwInputError(file, options.rawDims ? "--dims" : "--axes",
                        "applies to plain TIFF pages; this " + format + " file says its own layout");
}

// --level reads an OME-TIFF pyramid's SubIFDs; other TIFF layouts have one resolution.
void refuseLevel(const std::filesystem::path& file, const ReadOptions& options, const std::string& format) {
    if (options.level)
        throwInputError(file, "--level",
                        "chooses a level of an OME-TIFF pyramid (SubIFDs); this " + format + " has one resolution");
}

TiffLayout oneFileLayout(const std::filesystem::path& file, const ReadOptions& options, std::uint64_t cap) {
    TiffFile tiff(file, cap);
    std::vector<TiffPage> pages = tiff.readPages();
    const std::string description = tiff.firstDescription();
    if (looksLikeOmeXml(description)) {
        refusePageOptions(file, options, "OME-TIFF");
        return omeLayout(tiff, std::move(pages), parseOmeXml(description, file), options, cap);
    }
    if (isImageJDescription(description)) {
        refusePageOptions(file, options, "ImageJ");
        refuseLevel(file, options, "ImageJ file");
        return imagejLayout(tiff, std::move(pages), parseImageJDescription(description, file), options);
    }
    refuseLevel(file, options, "TIFF of plain pages");
    return pageLayout({file}, {std::move(pages)}, nullptr, options);
}

// Every file's pages as slices; the first file's ImageJ description, if any, for the spacing.
TiffLayout listLayout(const std::vector<std::filesystem::path>& files, const ReadOptions& options, std::uint64_t cap) {
    refuseLevel(files.front(), options, "list of TIFF files");
    std::vector<std::vector<TiffPage>> pages;
    std::optional<ImageJDescription> imagej;
    for (const auto& file : files) {
        TiffFile tiff(file, cap);
        pages.push_back(tiff.readPages());
        const std::string description = tiff.firstDescription();
        if (!isImageJDescription(description)) continue;
        const ImageJDescription parsed = parseImageJDescription(description, file);
        if (parsed.channels > 1 || parsed.frames > 1)
            throwInputError(file, "ImageDescription",
                            "is an ImageJ hyperstack with several channels or frames: give it alone, not in a list or folder");
        if (!imagej) imagej = parsed;
    }
    return pageLayout(files, std::move(pages), imagej ? &*imagej : nullptr, options);
}

std::array<SpatialAxis, 3> microscopyAxes(const std::string& unit) {
    return {SpatialAxis{"x", unit, AxisDirection::Unknown}, SpatialAxis{"y", unit, AxisDirection::Unknown},
            SpatialAxis{"z", unit, AxisDirection::Unknown}};
}

// Row 0 at the top and slice 0 nearest the viewer: a half turn about x, the grid's far corner in y
// and z moved to the origin so that the world box starts at 0 as the grid does.
Placement topDownPlacement(const glm::ivec3& dims, const glm::dvec3& spacing) {
    Placement placement;
    placement.rotation = glm::dquat(0.0, 1.0, 0.0, 0.0);
    placement.origin = {0.0, double(dims.y - 1) * spacing.y, double(dims.z - 1) * spacing.z};
    return placement;
}

std::vector<float> readVolume(const TiffLayout& layout, std::size_t step, std::uint64_t cap) {
    const TiffPage& first = layout.firstPage();
    const std::size_t planeValues = std::size_t(first.width) * first.height;
    std::vector<float> values(planeValues * layout.slices);
    std::map<std::size_t, std::unique_ptr<TiffFile>> open;  // this call's own handles: steps may be read in parallel
    for (std::size_t z = 0; z < layout.slices; ++z) {
        const TiffPlaneRef& plane = layout.planes[step * layout.slices + z];
        auto& tiff = open[plane.file];
        if (!tiff) tiff = std::make_unique<TiffFile>(layout.files[plane.file], cap);
        float* out = values.data() + z * planeValues;
        if (layout.contiguousOffset != 0) tiff->readContiguousPlane(first, layout.contiguousOffset, plane.page, layout.sample, out);
        else tiff->readPlane(layout.pages[plane.file][plane.page], plane.page, layout.sample, out);
    }
    return values;
}

}  // namespace

SourceSeries openTiff(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options) {
    const std::uint64_t cap = memoryCap(options.maxMemoryBytes);
    std::error_code error;
    const bool folder = inputs.size() == 1 && std::filesystem::is_directory(inputs.front(), error);
    const std::vector<std::filesystem::path> files = folder ? folderFiles(inputs.front()) : inputs;
    auto layout = std::make_shared<const TiffLayout>(files.size() == 1 && !folder ? oneFileLayout(files.front(), options, cap)
                                                                                  : listLayout(files, options, cap));
    const TiffPage& first = layout->firstPage();
    const glm::ivec3 dims{int(first.width), int(first.height), int(layout->slices)};

    SourceSeries source;
    source.name = (folder ? inputs.front().filename() : files.front().stem()).string();
    source.file = inputs.front();
    source.format = layout->format;
    source.axes = microscopyAxes(layout->unit);
    source.time = layout->time;
    source.notes = layout->notes;
    if (first.valueType() == ValueType::Float64 && first.sampleFormat != 3)
        source.notes.push_back("uint32 samples, described as float64 (which holds them exactly)");
    source.notes.push_back("image rows run top-down: y and z are turned about x so that row 0 is at the top");
    const Placement placement = topDownPlacement(dims, layout->spacing);
    for (std::size_t index = 0; index < layout->steps; ++index) {
        SourceStep step;
        step.time = layout->times[index];
        RectilinearGrid grid;
        grid.dims = dims;
        grid.spacing = layout->spacing;
        step.grid = grid;
        step.placement = placement;
        step.type = first.valueType();
        step.file = layout->files[layout->planes[index * layout->slices].file];
        source.steps.push_back(step);
    }
    source.readStep = [layout, dims, cap](std::size_t index) {
        std::vector<float> values = readVolume(*layout, index, cap);
        refuseInfinities(values, dims, layout->files[layout->planes[index * layout->slices].file], index);
        return values;
    };
    return source;
}

bool hasTiffSignature(const std::filesystem::path& file) {
    // Classic TIFF and BigTIFF, little- and big-endian.
    const std::string start = fileStart(file, 4);
    for (const std::string_view magic : {std::string_view("II*\0", 4), std::string_view("MM\0*", 4),
                                         std::string_view("II+\0", 4), std::string_view("MM\0+", 4)})
        if (hasMagicAt(start, 0, magic)) return true;
    return false;
}

bool isTiffFolder(const std::filesystem::path& folder) {
    std::error_code error;
    if (std::filesystem::exists(folder / "series.json", error)) return false;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (isTiffName(entry.path())) return true;
    return false;
}

}  // namespace tstyles
