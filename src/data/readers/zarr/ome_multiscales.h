// The OME-NGFF "multiscales" metadata of an image store: 0.4 in a Zarr v2 group's `.zattrs`, 0.5 in
// a Zarr v3 group's `zarr.json` (attributes.ome); 0.1 to 0.3 spellings are read too. Axes with their
// kind and unit, and each resolution level's path, scale and translation (the level's transforms
// composed with the multiscale's own).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tstyles {

enum class OmeAxisType { Time, Channel, Space };

struct OmeAxis {
    std::string name;
    OmeAxisType type = OmeAxisType::Space;
    std::string unit;  // as the file spells it ("micrometer", "second"); empty: none given
};

struct OmeLevel {
    std::string path;  // the array's folder, relative to the store
    std::vector<double> scale;        // per axis
    std::vector<double> translation;  // per axis
};

struct OmeMultiscales {
    std::filesystem::path store;
    std::filesystem::path attributesFile;  // .zattrs or zarr.json, for messages
    int zarrFormat = 2;
    std::string version;  // "0.4", "0.5", ... ; empty: not given
    std::string name;
    std::vector<OmeAxis> axes;
    std::vector<OmeLevel> levels;  // finest first
    std::vector<std::string> channelLabels;  // omero.channels[].label where given
};

// Reads the first multiscales image of the store folder; anything missing, malformed or of a kind
// this reader cannot show is an InputError naming the attributes file and the field.
OmeMultiscales readOmeMultiscales(const std::filesystem::path& store);

// The group metadata file of a store folder that holds one (zarr.json, .zattrs, .zgroup), or empty.
std::filesystem::path zarrGroupFile(const std::filesystem::path& folder);

}  // namespace tstyles
