// Structured grids named by manifests: dims, a little-endian float32 coordinates file, validation.
#include "structured_grid_files.h"

#include <bit>
#include <cstdint>
#include <string>

#include "raw_values.h"
#include "tstyles/core/user_paths.h"

namespace tstyles {
namespace {

constexpr std::uint64_t kMaxNodesPerGrid = std::uint64_t(1) << 32;

float decodeFloat32(const std::uint8_t* bytes) {
    const std::uint32_t bits = std::uint32_t(bytes[0]) | (std::uint32_t(bytes[1]) << 8) |
                               (std::uint32_t(bytes[2]) << 16) | (std::uint32_t(bytes[3]) << 24);
    return std::bit_cast<float>(bits);
}

std::filesystem::path resolve(const JsonField& name) {
    const std::string text = name.string();
    if (text.empty()) name.fail("must name a file");
    requireUsablePathName({name.file(), name.path()}, text);
    const std::filesystem::path file = text;
    return file.is_absolute() ? file : name.file().parent_path() / file;
}

}  // namespace

StructuredGrid StructuredGridFiles::read(const JsonField& field, std::size_t stepIndex) {
    field.allowOnlyKeys({"type", "dims", "coordinates"});
    const glm::ivec3 dims = readGridDims(field.member("dims"), kMaxNodesPerGrid,
                                         {"expected 3 node counts (x, y, z)",
                                          "a grid needs two nodes along each axis to have cells",
                                          "too many nodes for one grid"});
    const JsonField coordinates = field.member("coordinates");
    coordinates.allowOnlyKeys({"file"});
    const JsonField fileField = coordinates.member("file");
    const std::filesystem::path file = resolve(fileField);
    const auto key = std::make_pair(file, std::array<int, 3>{dims.x, dims.y, dims.z});
    if (const auto known = grids_.find(key); known != grids_.end()) return known->second;

    const std::size_t nodeCount = std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
    const std::string layout = std::to_string(dims.x) + " x " + std::to_string(dims.y) + " x " +
                               std::to_string(dims.z) + " nodes, 3 float32 each";
    const std::vector<std::uint8_t> bytes =
        readExactBytes({field.file(), fileField.path(), stepIndex, file}, "coordinates file", nodeCount * 12, layout);
    std::vector<glm::vec3> nodes(nodeCount);
    for (std::size_t node = 0; node < nodeCount; ++node)
        for (int axis = 0; axis < 3; ++axis) nodes[node][axis] = decodeFloat32(&bytes[node * 12 + std::size_t(axis) * 4]);

    StructuredGrid grid = makeStructuredGrid(dims, std::move(nodes), file);
    if (const auto problem = findGridProblem(grid))
        fileField.fail("grid '" + file.string() + "' of time-step " + std::to_string(stepIndex) + ": " + *problem);
    grids_.emplace(key, grid);
    return grid;
}

}  // namespace tstyles
