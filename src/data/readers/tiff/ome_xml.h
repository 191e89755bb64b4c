// The OME-XML of an OME-TIFF's first ImageDescription: each Image's Pixels (sizes, order, physical
// sizes, time increment), its TiffData (which IFD holds which plane) and its Planes' DeltaT.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tstyles {

struct OmeTiffData {
    std::optional<std::size_t> ifd;
    std::size_t firstZ = 0, firstC = 0, firstT = 0;
    std::optional<std::size_t> planeCount;
    std::string fileName;  // UUID FileName: the planes are in that file
};

struct OmePlane {
    std::size_t theZ = 0, theC = 0, theT = 0;
    std::optional<double> deltaT;
    std::string deltaTUnit = "s";
};

struct OmeImage {
    std::string id;
    std::string name;
    std::string dimensionOrder = "XYZCT";
    std::size_t sizeX = 0, sizeY = 0, sizeZ = 1, sizeC = 1, sizeT = 1;
    std::size_t samplesPerPixel = 1;  // of its first Channel: RGB planes hold 3 channels each
    std::optional<double> physicalSizeX, physicalSizeY, physicalSizeZ;
    std::string physicalSizeXUnit = "µm", physicalSizeYUnit = "µm", physicalSizeZUnit = "µm";
    std::optional<double> timeIncrement;
    std::string timeIncrementUnit = "s";
    std::vector<OmeTiffData> tiffData;
    std::vector<OmePlane> planes;
};

bool looksLikeOmeXml(const std::string& description);

// Every Image with its Pixels; element names match with or without a namespace prefix. XML that
// does not parse, a size that is not a count or a physical size that is not a positive number is
// an InputError naming `file` and the attribute.
std::vector<OmeImage> parseOmeXml(const std::string& xml, const std::filesystem::path& file);

// The files an Image's planes lie in: `file` itself first, then each other UUID FileName its
// TiffData names (OME-TIFF split over files, one per time point say), in the order first named.
std::vector<std::string> omeFileNames(const OmeImage& image, const std::filesystem::path& file);

struct OmePlaneRef {
    std::size_t file = 0;  // into omeFileNames
    std::size_t ifd = 0;
};

// The file and IFD of each plane of `image` (planes in DimensionOrder, the first letter after XY
// fastest), from its TiffData; without TiffData the planes are IFDs `firstIfd`, `firstIfd` + 1, ...
// of `file`. `ifdCounts` holds each of omeFileNames' IFD count. A plane no TiffData names or an
// IFD past its file's count are InputErrors naming `file`.
std::vector<OmePlaneRef> omePlaneRefs(const OmeImage& image, const std::vector<std::size_t>& ifdCounts,
                                      std::size_t firstIfd, const std::filesystem::path& file);

// The index of plane (z, c, t) in the DimensionOrder.
std::size_t omePlaneIndex(const OmeImage& image, std::size_t z, std::size_t c, std::size_t t);

}  // namespace tstyles
