// OME-XML through pugixml: only the attributes that place and time the planes are read.
#include "ome_xml.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <pugixml.hpp>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

// "ome:Pixels" and "Pixels" are the same element.
bool isElementNamed(const pugi::xml_node& node, const char* name) {
    const char* full = node.name();
    const char* colon = std::strrchr(full, ':');
    return std::strcmp(colon ? colon + 1 : full, name) == 0;
}

std::vector<pugi::xml_node> childrenNamed(const pugi::xml_node& parent, const char* name) {
    std::vector<pugi::xml_node> found;
    for (pugi::xml_node child : parent.children())
        if (child.type() == pugi::node_element && isElementNamed(child, name)) found.push_back(child);
    return found;
}

std::string attributeField(const char* element, const char* attribute) {
    return std::string("OME-XML ") + element + " " + attribute;
}

std::optional<double> omeNumber(const pugi::xml_node& node, const char* attribute, const std::filesystem::path& file,
                             bool positive) {
    const pugi::xml_attribute found = node.attribute(attribute);
    if (!found) return std::nullopt;
    const std::string text = found.value();
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || (positive ? value <= 0.0 : value < 0.0))
        throwInputError(file, attributeField(node.name(), attribute),
                        "\"" + text + "\" is not a " + (positive ? "positive" : "non-negative") + " number");
    return value;
}

std::optional<std::size_t> omeCount(const pugi::xml_node& node, const char* attribute, const std::filesystem::path& file) {
    const std::optional<double> value = omeNumber(node, attribute, file, false);
    if (!value) return std::nullopt;
    if (*value != std::floor(*value) || *value > 1e12)
        throwInputError(file, attributeField(node.name(), attribute), "is not a count");
    return std::size_t(*value);
}

std::string omeText(const pugi::xml_node& node, const char* attribute, const std::string& fallback) {
    const pugi::xml_attribute found = node.attribute(attribute);
    return found ? std::string(found.value()) : fallback;
}

OmeTiffData readTiffData(const pugi::xml_node& node, const std::filesystem::path& file) {
    OmeTiffData data;
    data.ifd = omeCount(node, "IFD", file);
    data.firstZ = omeCount(node, "FirstZ", file).value_or(0);
    data.firstC = omeCount(node, "FirstC", file).value_or(0);
    data.firstT = omeCount(node, "FirstT", file).value_or(0);
    data.planeCount = omeCount(node, "PlaneCount", file);
    for (const pugi::xml_node& uuid : childrenNamed(node, "UUID")) data.fileName = omeText(uuid, "FileName", "");
    return data;
}

OmeImage readOmeImage(const pugi::xml_node& imageNode, const pugi::xml_node& pixels, const std::filesystem::path& file) {
    OmeImage image;
    image.id = omeText(imageNode, "ID", "");
    image.name = omeText(imageNode, "Name", "");
    image.dimensionOrder = omeText(pixels, "DimensionOrder", "XYZCT");
    const auto size = [&](const char* attribute) {
        const std::optional<std::size_t> value = omeCount(pixels, attribute, file);
        if (!value || *value == 0) throwInputError(file, attributeField("Pixels", attribute), "is missing or 0");
        return *value;
    };
    image.sizeX = size("SizeX");
    image.sizeY = size("SizeY");
    image.sizeZ = size("SizeZ");
    image.sizeC = size("SizeC");
    image.sizeT = size("SizeT");
    image.physicalSizeX = omeNumber(pixels, "PhysicalSizeX", file, true);
    image.physicalSizeY = omeNumber(pixels, "PhysicalSizeY", file, true);
    image.physicalSizeZ = omeNumber(pixels, "PhysicalSizeZ", file, true);
    image.physicalSizeXUnit = omeText(pixels, "PhysicalSizeXUnit", image.physicalSizeXUnit);
    image.physicalSizeYUnit = omeText(pixels, "PhysicalSizeYUnit", image.physicalSizeYUnit);
    image.physicalSizeZUnit = omeText(pixels, "PhysicalSizeZUnit", image.physicalSizeZUnit);
    image.timeIncrement = omeNumber(pixels, "TimeIncrement", file, true);
    image.timeIncrementUnit = omeText(pixels, "TimeIncrementUnit", image.timeIncrementUnit);
    for (const pugi::xml_node& channel : childrenNamed(pixels, "Channel")) {
        image.samplesPerPixel = omeCount(channel, "SamplesPerPixel", file).value_or(1);
        if (image.samplesPerPixel == 0) throwInputError(file, attributeField("Channel", "SamplesPerPixel"), "is 0");
        break;  // the first Channel says how many samples a plane's pixel holds
    }
    for (const pugi::xml_node& data : childrenNamed(pixels, "TiffData")) image.tiffData.push_back(readTiffData(data, file));
    for (const pugi::xml_node& planeNode : childrenNamed(pixels, "Plane")) {
        OmePlane plane;
        plane.theZ = omeCount(planeNode, "TheZ", file).value_or(0);
        plane.theC = omeCount(planeNode, "TheC", file).value_or(0);
        plane.theT = omeCount(planeNode, "TheT", file).value_or(0);
        plane.deltaT = omeNumber(planeNode, "DeltaT", file, false);
        plane.deltaTUnit = omeText(planeNode, "DeltaTUnit", plane.deltaTUnit);
        image.planes.push_back(plane);
    }
    return image;
}

std::size_t planeChannels(const OmeImage& image) { return std::max<std::size_t>(1, image.sizeC / image.samplesPerPixel); }

}  // namespace

bool looksLikeOmeXml(const std::string& description) {
    return description.find("<OME") != std::string::npos || description.find(":OME") != std::string::npos;
}

std::vector<OmeImage> parseOmeXml(const std::string& xml, const std::filesystem::path& file) {
    pugi::xml_document document;
    const pugi::xml_parse_result parsed = document.load_string(xml.c_str());
    if (!parsed)
        throwInputError(file, "ImageDescription (OME-XML)",
                        std::string("does not parse: ") + parsed.description() + " at byte " + std::to_string(parsed.offset));
    pugi::xml_node root;
    for (pugi::xml_node child : document.children())
        if (child.type() == pugi::node_element && isElementNamed(child, "OME")) root = child;
    if (!root) throwInputError(file, "ImageDescription (OME-XML)", "has no OME root element");
    std::vector<OmeImage> images;
    for (const pugi::xml_node& imageNode : childrenNamed(root, "Image"))
        for (const pugi::xml_node& pixels : childrenNamed(imageNode, "Pixels")) {
            images.push_back(readOmeImage(imageNode, pixels, file));
            break;
        }
    if (images.empty()) throwInputError(file, "ImageDescription (OME-XML)", "has no Image with Pixels");
    return images;
}

std::size_t omePlaneIndex(const OmeImage& image, std::size_t z, std::size_t c, std::size_t t) {
    std::size_t index = 0, stride = 1;
    for (std::size_t letter = 2; letter < image.dimensionOrder.size(); ++letter) {
        const char axis = image.dimensionOrder[letter];
        const std::size_t coordinate = axis == 'Z' ? z : axis == 'C' ? c : t;
        const std::size_t size = axis == 'Z' ? image.sizeZ : axis == 'C' ? planeChannels(image) : image.sizeT;
        index += coordinate * stride;
        stride *= size;
    }
    return index;
}

std::vector<std::string> omeFileNames(const OmeImage& image, const std::filesystem::path& file) {
    std::vector<std::string> names{file.filename().string()};
    for (const OmeTiffData& data : image.tiffData)
        if (!data.fileName.empty() && std::find(names.begin(), names.end(), data.fileName) == names.end()) {
            if (data.fileName.find('/') != std::string::npos || data.fileName.find('\\') != std::string::npos ||
                data.fileName == "." || data.fileName == "..")
                throwInputError(file, "OME-XML TiffData UUID FileName",
                                "\"" + data.fileName + "\" is not a file name beside this file");
            names.push_back(data.fileName);
        }
    return names;
}

std::vector<OmePlaneRef> omePlaneRefs(const OmeImage& image, const std::vector<std::size_t>& ifdCounts,
                                      std::size_t firstIfd, const std::filesystem::path& file) {
    const std::string& order = image.dimensionOrder;
    if (order.size() != 5 || order.compare(0, 2, "XY") != 0 || order.find('Z') == std::string::npos ||
        order.find('C') == std::string::npos || order.find('T') == std::string::npos)
        throwInputError(file, "OME-XML Pixels DimensionOrder", "\"" + order + "\" is not XY followed by Z, C and T");
    if (image.sizeC % image.samplesPerPixel != 0)
        throwInputError(file, "OME-XML Pixels SizeC", "is not a multiple of the Channel's SamplesPerPixel");
    const std::vector<std::string> names = omeFileNames(image, file);
    double ifdTotal = 0.0;
    for (std::size_t count : ifdCounts) ifdTotal += double(count);
    const double planes = double(image.sizeZ) * double(planeChannels(image)) * double(image.sizeT);
    if (planes > ifdTotal)
        throwInputError(file, "OME-XML Pixels",
                        "SizeZ x SizeC x SizeT = " + std::to_string(std::uint64_t(planes)) + " planes, the file" +
                            (names.size() > 1 ? "s have" : " has") + " only " +
                            std::to_string(std::uint64_t(ifdTotal)) + " IFDs");
    constexpr std::size_t kUnmapped = std::size_t(-1);
    std::vector<OmePlaneRef> refs(std::size_t(planes), OmePlaneRef{0, image.tiffData.empty() ? 0 : kUnmapped});
    if (image.tiffData.empty())
        for (std::size_t plane = 0; plane < refs.size(); ++plane) refs[plane].ifd = firstIfd + plane;
    for (const OmeTiffData& data : image.tiffData) {
        const std::size_t fileIndex = data.fileName.empty()
                                          ? 0
                                          : std::size_t(std::find(names.begin(), names.end(), data.fileName) -
                                                        names.begin());
        const std::size_t ifdCount = ifdCounts[fileIndex];
        if (data.firstZ >= image.sizeZ || data.firstC >= planeChannels(image) || data.firstT >= image.sizeT)
            throwInputError(file, "OME-XML TiffData", "FirstZ, FirstC or FirstT is past the Pixels' sizes");
        const std::size_t start = omePlaneIndex(image, data.firstZ, data.firstC, data.firstT);
        const std::size_t ifd = data.ifd.value_or(0);
        // A TiffData that names another file without IFD or PlaneCount is that file's one plane.
        const std::size_t planeCount =
            data.planeCount.value_or(data.ifd || fileIndex != 0 ? 1 : refs.size() - start);
        if (planeCount > refs.size() - start || ifd + planeCount > ifdCount)
            throwInputError(file, "OME-XML TiffData",
                            "IFD " + std::to_string(ifd) + " PlaneCount " + std::to_string(planeCount) +
                                " runs past the planes or past the " + std::to_string(ifdCount) + " IFDs of " +
                                names[fileIndex]);
        for (std::size_t k = 0; k < planeCount; ++k) refs[start + k] = {fileIndex, ifd + k};
    }
    for (std::size_t plane = 0; plane < refs.size(); ++plane)
        if (refs[plane].ifd >= ifdCounts[refs[plane].file])  // unmapped, or past the IFDs there are
            throwInputError(file, "OME-XML TiffData",
                            "no IFD for plane " + std::to_string(plane) + " of " + std::to_string(refs.size()));
    return refs;
}

}  // namespace tstyles
