// The textures a series takes on the GPU, worked out before anything is allocated: GpuSeries
// allocates from this plan, and the GPU memory budget (gpu_memory_budget.h) weighs series by it, so
// an estimate is what an upload allocates. GL-free.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/render/atlas_layout.h"
#include "tstyles/render/packed_aligned_atlas.h"

namespace tstyles {

// How a series is stored, where a memory budget may choose: the density precision and whether a
// series that suits it also gets the packed atlas (a faster path to the same image).
struct SeriesStorage {
    DensityPrecision precision = DensityPrecision::Bits16;
    bool packedAtlas = true;

    bool operator==(const SeriesStorage& other) const = default;
};

// What the plan needs to know of a series: its time-steps' dims and the properties that add
// channels or textures. Made once per series (shapeOf scans every value for missing ones);
// scaledShape gives the shape of the same series read coarser.
struct SeriesShape {
    std::vector<glm::ivec3> dims;            // per time-step
    bool missingValues = false;
    bool masks = false;
    bool packable = false;                   // suitsPackedAtlasAt16Bits
    PackedValidity packedValidity = PackedValidity::None;
    std::vector<glm::ivec3> inverseMapDims;  // per distinct structured grid
};
SeriesShape shapeOf(const Series& series);

// One texture of the plan: its name in messages, its size in texels and its bytes per texel.
struct PlannedTexture {
    const char* name;
    glm::ivec3 size{0};
    std::size_t texelBytes = 0;

    std::size_t bytes() const {
        return std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z) * texelBytes;
    }
};

struct SeriesTexturePlan {
    SeriesStorage storage;     // packedAtlas is false where the series does not suit it
    int densityChannels = 1;   // density, validity, mask (densityChannelCount)
    AtlasLayout density;       // the volume atlas
    AtlasLayout occupancy;     // one texel per brick of each time-step
    std::optional<AtlasLayout> packed;   // four time-steps per RGBA16 texel
    glm::ivec3 packedBricks{0};          // the packed atlas' occupancy (the grid's bricks)
    PackedValidity packedValidity = PackedValidity::None;
    glm::ivec3 sharedValiditySize{1};    // PackedValidity::Shared: the grid's dims
    AtlasLayout inverseMaps;             // RGBA32F, one texel even without structured grids

    // Every texture GpuSeries allocates, with the size and format it allocates.
    std::vector<PlannedTexture> textures() const;
};

// The plan of `shape` stored as `storage`. Throws InputError (field "volume atlas") when an atlas
// does not fit into one 3D texture of `maxTextureSize` texels per side.
SeriesTexturePlan planSeriesTextures(const SeriesShape& shape, const SeriesStorage& storage, int maxTextureSize);
// The same, with no plan instead of the InputError.
std::optional<SeriesTexturePlan> tryPlanSeriesTextures(const SeriesShape& shape, const SeriesStorage& storage,
                                                       int maxTextureSize);

std::size_t totalBytes(const std::vector<PlannedTexture>& textures);
std::size_t largestBytes(const std::vector<PlannedTexture>& textures);

// Bricks of empty-space skipping along each axis of a time-step of `dims` (brick_occupancy.h).
glm::ivec3 brickCountsOf(glm::ivec3 dims);

}  // namespace tstyles
