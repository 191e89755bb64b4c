// A series as the GPU holds it: all densities in one 3D atlas texture (masks in a second one), a
// table describing each time-step, and one proxy (a box, or a beam fan's mesh) per distinct grid
// and placement. Built once per series.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/data/series.h"
#include "tstyles/gl/objects.h"
#include "tstyles/render/atlas_layout.h"
#include "tstyles/render/brick_occupancy.h"
#include "tstyles/render/gpu_structured_grids.h"
#include "tstyles/render/packed_aligned_atlas.h"
#include "tstyles/render/series_texture_plan.h"

namespace tstyles {

class GpuSeries {
public:
    // Uploads every time-step. Throws InputError if the series does not fit into one 3D texture or
    // into GPU memory.
    explicit GpuSeries(const Series& series);
    // The same stored as `storage` says (a GPU memory budget's choice) rather than as read.
    GpuSeries(const Series& series, const SeriesStorage& storage);

    std::size_t timeStepCount() const { return timeStepCount_; }
    // Layers of the entry/exit buffers: one per distinct grid and placement.
    std::size_t proxyCount() const { return proxyCount_; }
    // Of those, the layers drawn as instanced boxes, and the vertices of the proxy mesh (beam fans,
    // then the boundary faces of structured grids).
    std::size_t proxyBoxCount() const { return proxyBoxCount_; }
    std::size_t proxyMeshVertexCount() const { return proxyMeshVertexCount_; }
    const GpuStructuredGrids& structuredGrids() const { return *structuredGrids_; }
    const AtlasLayout& layout() const { return layout_; }
    bool hasMasks() const { return hasMasks_; }
    // Whether every time-step's world -> voxel map is affine (TimeStepInfo.flags.x).
    bool allAffine() const { return allAffine_; }
    // Whether any time-step has an uneven rectilinear axis (node lists in the uneven-axis table).
    bool hasUnevenAxes() const { return hasUnevenAxes_; }
    // Whether an uneven axis' lookup buckets may hold several nodes (UnevenAxisTable::crowdedBuckets).
    bool hasCrowdedUnevenAxes() const { return hasCrowdedUnevenAxes_; }
    // Whether any time-step is a beam (sonar) grid.
    bool hasBeamGrids() const { return hasBeamGrids_; }
    // Whether any time-step is a rectilinear grid (even or uneven axes).
    bool hasRectilinearGrids() const { return hasRectilinearGrids_; }
    // Whether every beam grid has evenly spaced beams on both axes (a beam index is linear in its
    // angle; shaders/beam_grid.glsl, EVEN_BEAMS). False without beam grids.
    bool allBeamsEven() const { return allBeamsEven_; }
    // True when the density atlas holds (density * validity, validity) pairs.
    bool hasMissingValues() const { return hasMissingValues_; }
    // The density atlas' storage: R8, R16 or R32F (RG8, RG16, RG32F with missing values), from
    // Series::precision.
    DensityPrecision precision() const { return precision_; }
    // Fully aligned series (suitsPackedAtlas): four time-steps per texel, next to the atlas above;
    // null for other series.
    const PackedAlignedAtlas* packedAtlas() const { return packedAtlas_ ? &*packedAtlas_ : nullptr; }
    // Bytes of texture memory as the driver reports the textures allocated: the density atlas
    // (masks included), the brick occupancy, the inverse maps, the packed atlas.
    std::size_t textureBytes() const;
    // The plan the textures were allocated from (series_texture_plan.h).
    const SeriesTexturePlan& texturePlan() const { return plan_; }

    // Marks each brick visible or empty under the STF (its baked table), for empty-space skipping.
    // Per transfer-function change, not per frame.
    void updateOccupancy(const std::vector<glm::vec4>& stfTable);
    // Under the STF of the last updateOccupancy: the share of all time-steps' bricks that are
    // empty, and of the packed atlas' bricks that are empty in every time-step (0 without one).
    double emptyBrickFraction() const { return emptyBrickFraction_; }
    double emptyPackedBrickFraction() const { return packedEmptyBrickFraction_; }

    // Binds the atlases and the time-step and proxy tables at their binding points.
    void bind() const;

private:
    std::size_t timeStepCount_ = 0;
    std::size_t proxyCount_ = 0;
    std::size_t proxyBoxCount_ = 0;
    std::size_t proxyMeshVertexCount_ = 0;
    bool hasMasks_ = false;
    bool allAffine_ = true;
    bool hasUnevenAxes_ = true;
    bool hasCrowdedUnevenAxes_ = true;
    bool hasBeamGrids_ = false;
    bool hasRectilinearGrids_ = true;
    bool allBeamsEven_ = false;
    bool hasMissingValues_ = false;
    DensityPrecision precision_ = DensityPrecision::Bits16;
    SeriesTexturePlan plan_;
    AtlasLayout layout_;
    Texture densityAtlas_;
    std::vector<BrickGrid> brickGrids_;
    AtlasLayout occupancyLayout_;
    double emptyBrickFraction_ = 0.0;
    double packedEmptyBrickFraction_ = 0.0;
    Texture occupancyAtlas_;
    std::optional<PackedAlignedAtlas> packedAtlas_;
    Buffer timeStepTable_;
    Buffer proxyTable_;
    std::optional<GpuStructuredGrids> structuredGrids_;
    Buffer unevenAxisTable_;  // shaders/uneven_axes.glsl
    Buffer axisNodeTable_;
    Buffer unevenCellTable_;
    Texture unevenCells_;  // a buffer texture over unevenCellTable_
    Buffer beamAngleTable_;
    Buffer proxyMeshTable_;
};

}  // namespace tstyles
