// The textures of a series on the GPU and their bytes, from its shape alone.
#include "tstyles/render/series_texture_plan.h"

#include <algorithm>
#include <numeric>

#include "tstyles/core/errors.h"
#include "tstyles/data/inverse_map.h"
#include "tstyles/data/read_options.h"
#include "tstyles/render/brick_occupancy.h"
#include "tstyles/render/density_texels.h"

namespace tstyles {
namespace {

// The inverse maps of the distinct structured grids, as GpuStructuredGrids tells grids apart.
std::vector<glm::ivec3> inverseMapDimsOf(const Series& series) {
    std::vector<const StructuredGrid*> grids;
    for (const TimeStep& step : series.steps) {
        const StructuredGrid* grid = step.structured();
        if (!grid) continue;
        if (std::none_of(grids.begin(), grids.end(), [grid](const StructuredGrid* other) { return other->nodes == grid->nodes; }))
            grids.push_back(grid);
    }
    std::vector<glm::ivec3> dims;
    for (const StructuredGrid* grid : grids) dims.push_back(inverseMapDims(*grid));
    return dims;
}

// Bytes per texel of the density atlas: R, RG or RGB at the storage's precision.
std::size_t densityTexelBytes(const SeriesTexturePlan& plan) {
    return bytesPerDensity(plan.storage.precision) * std::size_t(plan.densityChannels);
}

}  // namespace

glm::ivec3 brickCountsOf(glm::ivec3 dims) {
    return glm::max((dims - 1 + kBrickSize - 1) / kBrickSize, glm::ivec3(1));
}

SeriesShape shapeOf(const Series& series) {
    SeriesShape shape;
    for (const TimeStep& step : series.steps) shape.dims.push_back(step.dims());
    shape.missingValues = hasMissingValues(series);
    shape.masks = series.hasMasks();
    shape.packable = suitsPackedAtlasAt16Bits(series);
    if (shape.packable) shape.packedValidity = packedValidityOf(series);
    shape.inverseMapDims = inverseMapDimsOf(series);
    return shape;
}

SeriesTexturePlan planSeriesTextures(const SeriesShape& shape, const SeriesStorage& storage, int maxTextureSize) {
    SeriesTexturePlan plan;
    plan.storage = storage;
    plan.storage.packedAtlas =
        storage.packedAtlas && shape.packable && storage.precision == DensityPrecision::Bits16;
    plan.densityChannels = densityChannelCount(shape.missingValues, shape.masks);
    plan.density = planAtlas(shape.dims, maxTextureSize);
    std::vector<glm::ivec3> brickCounts;
    for (const glm::ivec3& dims : shape.dims) brickCounts.push_back(brickCountsOf(dims));
    plan.occupancy = planAtlas(brickCounts, maxTextureSize);
    if (plan.storage.packedAtlas) {
        const std::size_t groups = (shape.dims.size() + kTimeStepsPerTexel - 1) / kTimeStepsPerTexel;
        plan.packed = planAtlas(std::vector<glm::ivec3>(groups, shape.dims.front()), maxTextureSize);
        plan.packedBricks = brickCounts.front();
        plan.packedValidity = shape.packedValidity;
        if (shape.packedValidity == PackedValidity::Shared) plan.sharedValiditySize = shape.dims.front();
    }
    plan.inverseMaps = planAtlas(shape.inverseMapDims.empty() ? std::vector<glm::ivec3>{glm::ivec3(1)}
                                                              : shape.inverseMapDims,
                                 maxTextureSize);
    return plan;
}

std::optional<SeriesTexturePlan> tryPlanSeriesTextures(const SeriesShape& shape, const SeriesStorage& storage,
                                                       int maxTextureSize) {
    try {
        return planSeriesTextures(shape, storage, maxTextureSize);
    } catch (const InputError&) {
        return std::nullopt;  // an atlas larger than one 3D texture: a coarser plan may fit
    }
}

std::vector<PlannedTexture> SeriesTexturePlan::textures() const {
    std::vector<PlannedTexture> result{
        {"volume atlas", density.size, densityTexelBytes(*this)},
        {"brick occupancy", occupancy.size, 1},
        {"inverse maps", inverseMaps.size, 16},
    };
    if (packed) {
        const bool perGroup = packedValidity == PackedValidity::PerGroup;
        result.push_back({"packed atlas", packed->size, 8});
        result.push_back({"packed validity", perGroup ? packed->size : sharedValiditySize, perGroup ? 8u : 2u});
        // With group masks the occupancy sits beside each mask (RG32UI), else in a texture of its own.
        const bool masked = packed->brickOrigins.size() <= std::size_t(kMaxMaskedGroups);
        result.push_back({"packed occupancy", masked ? glm::ivec3(1) : packedBricks, 1});
        result.push_back({"packed group masks", masked ? packedBricks : glm::ivec3(1), 8});
        result.push_back({"packed change bounds", packedBricks, 4});
    }
    return result;
}

std::size_t totalBytes(const std::vector<PlannedTexture>& textures) {
    return std::accumulate(textures.begin(), textures.end(), std::size_t(0),
                           [](std::size_t sum, const PlannedTexture& texture) { return sum + texture.bytes(); });
}

std::size_t largestBytes(const std::vector<PlannedTexture>& textures) {
    std::size_t largest = 0;
    for (const PlannedTexture& texture : textures) largest = std::max(largest, texture.bytes());
    return largest;
}

}  // namespace tstyles
