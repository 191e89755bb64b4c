// Upload of a series into the volume atlas and the per-time-step tables.
#include "tstyles/render/gpu_series.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <variant>

#include <glm/gtc/matrix_transform.hpp>

#include "tstyles/core/errors.h"
#include "tstyles/data/beam_geometry.h"
#include "tstyles/data/read_options.h"
#include "tstyles/render/beam_angle_table.h"
#include "tstyles/render/shader_contract.h"
#include "tstyles/render/density_texels.h"
#include "tstyles/render/empty_brick_reach.h"
#include "tstyles/render/packed_aligned_atlas.h"
#include "tstyles/render/proxy_mesh.h"
#include "tstyles/render/series_texture_plan.h"
#include "tstyles/render/uneven_axis_table.h"

namespace tstyles {
namespace {

using contract::TimeStepInfo;

using contract::ProxyBox;

int maxTextureSize3D() {
    GLint size = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &size);
    return size;
}

void requireNoOutOfMemory(const Series& series, const char* what) {
    if (glGetError() == GL_OUT_OF_MEMORY)
        throwInputError(series.manifestPath, "", std::string("not enough GPU memory for the ") + what);
}

Texture createAtlas(GLenum format, const glm::ivec3& size) {
    Texture texture = Texture::create(GL_TEXTURE_3D);
    glTextureStorage3D(texture.id(), 1, format, size.x, size.y, size.z);
    texture.setFilter(GL_LINEAR, GL_LINEAR);
    texture.setClampToEdge();
    return texture;
}

bool shareProxy(const TimeStep& a, const TimeStep& b) {
    if (!(a.placement == b.placement) || a.grid.index() != b.grid.index()) return false;
    if (a.isBeam()) return a.beam() == b.beam();
    return a.rectilinear().extent() == b.rectilinear().extent();
}

// The proxy layer of every rectilinear and beam time-step; time-steps with the same grid and
// placement share one. Boxes get a proxy box, beam fans a proxy mesh. Structured time-steps get
// theirs from GpuStructuredGrids (-1 here).
std::vector<int> assignProxyLayers(const Series& series, std::vector<ProxyBox>& boxes,
                                   std::vector<ProxyMeshVertex>& mesh) {
    std::vector<int> layers;
    std::vector<std::size_t> firstStepOfLayer;
    for (std::size_t step = 0; step < series.size(); ++step) {
        const auto& timeStep = series.steps[step];
        if (timeStep.structured()) {
            layers.push_back(-1);
            continue;
        }
        int layer = -1;
        for (std::size_t candidate = 0; candidate < firstStepOfLayer.size(); ++candidate) {
            if (shareProxy(series.steps[firstStepOfLayer[candidate]], timeStep)) {
                layer = int(candidate);
                break;
            }
        }
        if (layer < 0) {
            layer = int(firstStepOfLayer.size());
            firstStepOfLayer.push_back(step);
            if (timeStep.isBeam())
                appendBeamProxyMesh(timeStep, layer, mesh);
            else
                boxes.push_back({glm::mat4(timeStep.placement.gridToWorld()),
                                 glm::vec4(glm::vec3(timeStep.rectilinear().extent()), float(layer))});
        }
        layers.push_back(layer);
    }
    return layers;
}

// Whether world -> voxel coordinates is one matrix product: evenly spaced rectilinear grids.
// Other grids (uneven axes, and the grid kinds still to come) take the general path in the shader.
bool hasAffineWorldToVoxel(const TimeStep& step) {
    const auto* grid = std::get_if<RectilinearGrid>(&step.grid);
    return grid && !grid->isUneven(0) && !grid->isUneven(1) && !grid->isUneven(2);
}

struct DensityTexelFormat {
    GLenum internalFormat;
    GLenum format;  // of the uploaded texels (densityTexelBytes): GL_RED, GL_RG or GL_RGB
    GLenum type;
};

// R8 / R16 / R32F for the density alone; a channel more for validity where values are missing
// (density * validity, validity) and one more for the mask in a series with masks.
DensityTexelFormat densityTexelFormat(DensityPrecision precision, int channels) {
    constexpr GLenum formats[] = {GL_RED, GL_RG, GL_RGB};
    constexpr GLenum bits8[] = {GL_R8, GL_RG8, GL_RGB8};
    constexpr GLenum bits16[] = {GL_R16, GL_RG16, GL_RGB16};
    constexpr GLenum bits32[] = {GL_R32F, GL_RG32F, GL_RGB32F};
    const std::size_t index = std::size_t(channels - 1);
    switch (precision) {
        case DensityPrecision::Bits8:
            return {bits8[index], formats[index], GLenum(GL_UNSIGNED_BYTE)};
        case DensityPrecision::Bits16:
            return {bits16[index], formats[index], GLenum(GL_UNSIGNED_SHORT)};
        case DensityPrecision::Bits32:
            break;
    }
    return {bits32[index], formats[index], GLenum(GL_FLOAT)};
}

// The manifest field that holds a beam axis' angles, for error messages.
std::string beamAngleField(std::size_t index, const std::vector<double>& anglesDeg, const char* axis) {
    return "time_steps[" + std::to_string(index) + "].grid." + axis +
           (areEvenBeamAngles(anglesDeg) ? "_deg" : "_angles_deg");
}

// TimeStepInfo.evenBeamFan of an evenly spaced fan: the first angles and the beams per radian, in
// float from the radians the beam angle buffer holds (from `azimuths` and `elevations` on), as the
// shader once worked them out at every sample.
glm::vec4 evenBeamFan(const std::vector<float>& beamAngles, int azimuths, int elevations, const glm::ivec3& dims) {
    const float firstAzimuth = beamAngles[std::size_t(azimuths)];
    const float lastAzimuth = beamAngles[std::size_t(azimuths + dims.x - 1)];
    const float firstElevation = beamAngles[std::size_t(elevations)];
    const float lastElevation = beamAngles[std::size_t(elevations + dims.y - 1)];
    return {firstAzimuth, float(dims.x - 1) / (lastAzimuth - firstAzimuth), firstElevation,
            float(dims.y - 1) / (lastElevation - firstElevation)};
}

// A time-step's row in the time-step table; beam grids also append their angles (radians) and the
// angles' lookup (render/beam_angle_table.h).
TimeStepInfo timeStepInfo(const Series& series, std::size_t index, const glm::ivec3& brickOrigin, int layer,
                          const glm::ivec3& occupancyOrigin, std::vector<float>& beamAngles) {
    const TimeStep& step = series.steps[index];
    TimeStepInfo info{};
    const glm::ivec3 dims = step.dims();
    info.brickOrigin = glm::vec4(glm::vec3(brickOrigin), 0.0f);
    info.dims = glm::vec4(glm::vec3(dims), step.mask ? 1.0f : 0.0f);
    info.layer = glm::ivec4(layer, 0, 0, 0);
    info.occupancyOrigin = glm::vec4(glm::vec3(occupancyOrigin), 0.0f);
    // Relative to the first time-step, so that float keeps the differences of large stamps (days
    // since 1950) that the linear-trend compositor needs.
    info.time = glm::vec4(float(step.time - series.steps.front().time), 0.0f, 0.0f, 0.0f);
    if (step.isBeam()) {
        const BeamGrid& grid = step.beam();
        info.worldToVoxel = glm::mat4(glm::inverse(step.placement.gridToWorld()));
        const int azimuths = appendBeamAngleRun(grid.azimuthDeg, beamAngles, series.manifestPath,
                                                beamAngleField(index, grid.azimuthDeg, "azimuth"));
        const int elevations = appendBeamAngleRun(grid.elevationDeg, beamAngles, series.manifestPath,
                                                  beamAngleField(index, grid.elevationDeg, "elevation"));
        info.grid = glm::ivec4(contract::GRID_BEAM, azimuths, elevations, 0);
        const float minRange = float(grid.minRange);
        const float maxRange = float(grid.maxRange);
        const float rangeSamplesPerUnit = float(dims.z - 1) / (maxRange - minRange);
        info.beamRange = glm::vec4(minRange, maxRange, float(grid.rangeSpacing()), rangeSamplesPerUnit);
        if (areEvenBeamAngles(grid.azimuthDeg) && areEvenBeamAngles(grid.elevationDeg))
            info.evenBeamFan = evenBeamFan(beamAngles, azimuths, elevations, dims);
        return info;
    }
    const StructuredGrid* structured = step.structured();
    const glm::dmat4 voxelToWorld =
        structured ? structuredBoxToWorld(*structured, step.placement)
                   : step.placement.gridToWorld() * glm::scale(glm::dmat4(1.0), voxelScale(step.rectilinear()));
    info.worldToVoxel = glm::mat4(glm::inverse(voxelToWorld));
    info.flags = glm::ivec4(hasAffineWorldToVoxel(step) ? 1 : 0, 0, 0, 0);
    // Structured grids are told apart by their own table (shaders/structured_grid.glsl).
    info.grid = glm::ivec4(contract::GRID_RECTILINEAR, 0, 0, 0);
    return info;
}

}  // namespace

GpuSeries::GpuSeries(const Series& series) : GpuSeries(series, SeriesStorage{series.precision, true}) {}

GpuSeries::GpuSeries(const Series& series, const SeriesStorage& storage)
    : densityAtlas_(Texture::create(GL_TEXTURE_3D)),
      occupancyAtlas_(Texture::create(GL_TEXTURE_3D)),
      timeStepTable_(Buffer::create()),
      proxyTable_(Buffer::create()),
      unevenAxisTable_(Buffer::create()),
      axisNodeTable_(Buffer::create()),
      unevenCellTable_(Buffer::create()),
      unevenCells_(Texture::create(GL_TEXTURE_BUFFER)),
      beamAngleTable_(Buffer::create()),
      proxyMeshTable_(Buffer::create()) {
    // Validation of structured grids happens on load; here they only need an inverse map and a mesh.
    timeStepCount_ = series.size();
    hasMasks_ = series.hasMasks();
    allAffine_ = std::all_of(series.steps.begin(), series.steps.end(), hasAffineWorldToVoxel);
    hasBeamGrids_ = std::any_of(series.steps.begin(), series.steps.end(), [](const TimeStep& step) { return step.isBeam(); });
    hasRectilinearGrids_ = std::any_of(series.steps.begin(), series.steps.end(), [](const TimeStep& step) {
        return std::holds_alternative<RectilinearGrid>(step.grid);
    });
    allBeamsEven_ = hasBeamGrids_ && std::all_of(series.steps.begin(), series.steps.end(), [](const TimeStep& step) {
                        if (!step.isBeam()) return true;
                        const BeamGrid& grid = step.beam();
                        return grid.azimuthDeg.size() >= 2 && grid.elevationDeg.size() >= 2 &&
                               areEvenBeamAngles(grid.azimuthDeg) && areEvenBeamAngles(grid.elevationDeg);
                    });
    const SeriesShape shape = shapeOf(series);
    plan_ = planSeriesTextures(shape, storage, maxTextureSize3D());
    layout_ = plan_.density;

    glGetError();  // start from a clean error state so that OUT_OF_MEMORY below is ours
    hasMissingValues_ = shape.missingValues;
    precision_ = storage.precision;
    const DensityTexelFormat texelFormat =
        densityTexelFormat(precision_, densityChannelCount(hasMissingValues_, hasMasks_));
    densityAtlas_ = createAtlas(texelFormat.internalFormat, layout_.size);
    // Validity reads as alpha; without missing values alpha is 1 everywhere (the default for
    // formats without alpha). The mask is the last channel (shaders/volume_sampling.glsl).
    if (hasMissingValues_) glTextureParameteri(densityAtlas_.id(), GL_TEXTURE_SWIZZLE_A, GL_GREEN);
    requireNoOutOfMemory(series, "volume atlas");

    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (std::size_t index = 0; index < series.size(); ++index) {
        const auto& step = series.steps[index];
        const glm::ivec3 size = step.dims();
        const glm::ivec3 origin = layout_.brickOrigins[index];
        const std::vector<std::uint8_t> texels = densityTexelBytes(step, hasMissingValues_, hasMasks_, precision_);
        glTextureSubImage3D(densityAtlas_.id(), 0, origin.x, origin.y, origin.z, size.x, size.y, size.z,
                            texelFormat.format, texelFormat.type, texels.data());
    }
    requireNoOutOfMemory(series, "volume atlas");

    // Empty-space skipping: a brick grid per time-step, packed like the volumes; its visibility is
    // filled in by updateOccupancy once the STF is known.
    std::vector<glm::ivec3> brickCounts;
    for (const auto& step : series.steps) {
        brickGrids_.push_back(computeBrickGrid(step));
        brickCounts.push_back(brickGrids_.back().bricks);
    }
    occupancyLayout_ = plan_.occupancy;
    occupancyAtlas_ = Texture::create(GL_TEXTURE_3D);
    glTextureStorage3D(occupancyAtlas_.id(), 1, GL_R8UI, occupancyLayout_.size.x, occupancyLayout_.size.y,
                       occupancyLayout_.size.z);
    occupancyAtlas_.setFilter(GL_NEAREST, GL_NEAREST);
    occupancyAtlas_.setClampToEdge();
    if (plan_.storage.packedAtlas) {
        packedAtlas_.emplace(series, brickGrids_.front().bricks, maxTextureSize3D());
        requireNoOutOfMemory(series, "packed atlas");
    }

    std::vector<ProxyBox> boxes;
    std::vector<ProxyMeshVertex> mesh;
    std::vector<int> layers = assignProxyLayers(series, boxes, mesh);
    const int boxAndFanLayers = 1 + std::accumulate(layers.begin(), layers.end(), -1,
                                                    [](int most, int layer) { return std::max(most, layer); });
    structuredGrids_.emplace(series, boxAndFanLayers, layers, mesh, maxTextureSize3D());
    requireNoOutOfMemory(series, "inverse maps of the structured grids");
    proxyCount_ = std::size_t(boxAndFanLayers + structuredGrids_->layerCount());
    proxyBoxCount_ = boxes.size();
    proxyMeshVertexCount_ = mesh.size();
    std::vector<TimeStepInfo> table;
    std::vector<float> beamAngles;
    for (std::size_t index = 0; index < series.size(); ++index) {
        table.push_back(timeStepInfo(series, index, layout_.brickOrigins[index], layers[index],
                                     occupancyLayout_.brickOrigins[index], beamAngles));
    }
    // Buffers bound to a binding point must not be empty, even where no shader reads them.
    if (boxes.empty()) boxes.push_back({});
    if (mesh.empty()) mesh.push_back({});
    if (beamAngles.empty()) beamAngles.push_back(0.0f);
    timeStepTable_.setData(std::as_bytes(std::span(table)), GL_STATIC_DRAW);
    beamAngleTable_.setData(std::as_bytes(std::span(beamAngles)), GL_STATIC_DRAW);
    proxyMeshTable_.setData(std::as_bytes(std::span(mesh)), GL_STATIC_DRAW);
    proxyTable_.setData(std::as_bytes(std::span(boxes)), GL_STATIC_DRAW);
    const UnevenAxisTable uneven = buildUnevenAxisTable(series);
    GLint maxBufferTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxBufferTexels);
    requireCellsFit(uneven, std::size_t(maxBufferTexels), series);
    hasUnevenAxes_ = std::any_of(uneven.steps.begin(), uneven.steps.end(), [](const contract::UnevenAxisInfo& info) {
        return glm::any(glm::greaterThanEqual(info.firstNode, glm::ivec4(0)));
    });
    hasCrowdedUnevenAxes_ = uneven.crowdedBuckets;
    unevenAxisTable_.setData(std::as_bytes(std::span(uneven.steps)), GL_STATIC_DRAW);
    axisNodeTable_.setData(std::as_bytes(std::span(uneven.positions)), GL_STATIC_DRAW);
    unevenCellTable_.setData(std::as_bytes(std::span(uneven.cells)), GL_STATIC_DRAW);
    glTextureBuffer(unevenCells_.id(), GL_RGBA32F, unevenCellTable_.id());
}

std::size_t GpuSeries::textureBytes() const {
    return densityAtlas_.allocatedBytes() + occupancyAtlas_.allocatedBytes() + structuredGrids_->gpuBytes() +
           (packedAtlas_ ? packedAtlas_->textureBytes() : 0);
}

void GpuSeries::updateOccupancy(const std::vector<glm::vec4>& stfTable) {
    const OpacityRangeMaximum opacity(stfTable);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    std::vector<std::vector<std::uint8_t>> visibilities;  // kept for the packed atlas only
    std::size_t bricks = 0, emptyBricks = 0;
    for (std::size_t index = 0; index < brickGrids_.size(); ++index) {
        const std::vector<std::uint8_t> visible = brickVisibility(brickGrids_[index], opacity);
        bricks += visible.size();
        emptyBricks += std::size_t(std::count(visible.begin(), visible.end(), std::uint8_t(0)));
        if (packedAtlas_) visibilities.push_back(visible);
        const glm::ivec3 origin = occupancyLayout_.brickOrigins[index];
        const glm::ivec3 size = brickGrids_[index].bricks;
        const std::vector<std::uint8_t> reach = emptyBrickReach(visible, size);
        glTextureSubImage3D(occupancyAtlas_.id(), 0, origin.x, origin.y, origin.z, size.x, size.y, size.z,
                            GL_RED_INTEGER, GL_UNSIGNED_BYTE, reach.data());
    }
    emptyBrickFraction_ = bricks ? double(emptyBricks) / double(bricks) : 0.0;
    if (packedAtlas_) packedEmptyBrickFraction_ = packedAtlas_->updateOccupancy(visibilities);
}

void GpuSeries::bind() const {
    densityAtlas_.bindToUnit(contract::ATLAS_UNIT);
    occupancyAtlas_.bindToUnit(contract::OCCUPANCY_UNIT);
    timeStepTable_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::TIME_STEP_BUFFER);
    proxyTable_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::PROXY_BUFFER);
    structuredGrids_->bind();
    unevenAxisTable_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::UNEVEN_AXIS_BUFFER);
    axisNodeTable_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::AXIS_NODE_BUFFER);
    unevenCells_.bindToUnit(contract::UNEVEN_CELL_UNIT);
    beamAngleTable_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::BEAM_ANGLE_BUFFER);
    proxyMeshTable_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::PROXY_MESH_BUFFER);
    if (packedAtlas_) packedAtlas_->bind();
}

}  // namespace tstyles
