// Choosing how a series is stored so that its textures fit a GPU memory budget.
#include "tstyles/render/gpu_memory_budget.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/data/coarser_series.h"
#include "tstyles/data/read_options.h"
#include "tstyles/render/lossless_precision.h"

namespace tstyles {
namespace {

// 2 % finer steps than that would take more plans than they save texels.
constexpr double kScaleStep = 1.02;

std::optional<std::size_t> fittingBytes(const SeriesShape& shape, const SeriesStorage& storage,
                                        const GpuMemoryLimits& limits) {
    const std::optional<SeriesTexturePlan> plan = tryPlanSeriesTextures(shape, storage, limits.maxTextureSize);
    if (!plan) return std::nullopt;
    const std::vector<PlannedTexture> textures = plan->textures();
    const std::size_t bytes = totalBytes(textures);
    if (bytes > limits.budgetBytes) return std::nullopt;
    if (limits.largestTextureBytes && largestBytes(textures) > *limits.largestTextureBytes) return std::nullopt;
    return bytes;
}

std::optional<std::size_t> totalBytesIfPlanned(const SeriesShape& shape, const SeriesStorage& storage,
                                               int maxTextureSize) {
    const std::optional<SeriesTexturePlan> plan = tryPlanSeriesTextures(shape, storage, maxTextureSize);
    return plan ? std::optional<std::size_t>(totalBytes(plan->textures())) : std::nullopt;
}

glm::ivec3 dimsWithMostVoxels(const std::vector<glm::ivec3>& dims) {
    return *std::max_element(dims.begin(), dims.end(), [](glm::ivec3 a, glm::ivec3 b) {
        return double(a.x) * a.y * a.z < double(b.x) * b.y * b.z;
    });
}

SeriesShape scaledShape(const SeriesShape& shape, double scale) {
    SeriesShape scaled = shape;
    for (glm::ivec3& dims : scaled.dims) dims = coarserDims(dims, scale);
    return scaled;
}

std::string dimsText(glm::ivec3 dims) {
    return std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" + std::to_string(dims.z);
}

std::string storageText(const SeriesStorage& storage, bool packable) {
    std::string text = std::to_string(precisionBits(storage.precision)) + "-bit";
    if (packable && storage.precision == DensityPrecision::Bits16)
        text += storage.packedAtlas ? " with the packed atlas" : " without the packed atlas";
    return text;
}

[[noreturn]] void refuse(const Series& series, const GpuMemoryLimits& limits, const GpuResidency& residency,
                         const std::string& why) {
    throwInputError(series.manifestPath, limits.budgetSource,
                    "the series needs " +
                        (residency.fullBytes ? byteCountText(double(*residency.fullBytes)) : std::string("more than one 3D texture")) +
                        " of GPU memory at full size, more than the " + byteCountText(double(limits.budgetBytes)) +
                        " budget, and " + why);
}

}  // namespace

GpuResidency fitToGpuMemory(const Series& series, const GpuMemoryLimits& limits) {
    const SeriesShape shape = shapeOf(series);
    GpuResidency residency;
    residency.requested = {series.precision, true};
    residency.fullDims = residency.chosenDims = dimsWithMostVoxels(shape.dims);
    residency.fullBytes = totalBytesIfPlanned(shape, residency.requested, limits.maxTextureSize);

    // At full resolution: every storage that shows the same values, fewest changes first.
    std::vector<SeriesStorage> lossless{residency.requested, {series.precision, false}};
    const auto choose = [&](const SeriesStorage& storage) {
        const std::optional<std::size_t> bytes = fittingBytes(shape, storage, limits);
        if (bytes) {
            residency.storage = storage;
            residency.chosenBytes = *bytes;
        }
        return bytes.has_value();
    };
    for (const SeriesStorage& storage : lossless)
        if (choose(storage)) return residency;
    for (DensityPrecision smaller : losslessSmallerPrecisions(series, series.precision))
        if (choose({smaller, true}) || choose({smaller, false})) return residency;

    if (!canCoarsen(series))
        refuse(series, limits, residency, "only rectilinear grids can be uploaded at a lower resolution");
    // The bytes scale with the texels, so the cube root of the excess is where the search starts.
    const std::optional<std::size_t> unpacked =
        totalBytesIfPlanned(shape, {series.precision, false}, limits.maxTextureSize);
    double scale = std::max(1.0, unpacked ? std::cbrt(double(*unpacked) / double(limits.budgetBytes)) : 1.0);
    for (;; scale *= kScaleStep) {
        const SeriesShape coarse = scaledShape(shape, scale);
        const auto chooseCoarse = [&](const SeriesStorage& storage) {
            const std::optional<std::size_t> bytes = fittingBytes(coarse, storage, limits);
            if (!bytes) return false;
            residency.storage = storage;
            residency.chosenBytes = *bytes;
            residency.scale = scale;
            residency.chosenDims = dimsWithMostVoxels(coarse.dims);
            return true;
        };
        if (chooseCoarse(residency.requested) || chooseCoarse({series.precision, false})) return residency;
        if (std::all_of(coarse.dims.begin(), coarse.dims.end(), [](glm::ivec3 dims) { return dims == glm::ivec3(2); }))
            refuse(series, limits, residency, "does not fit even at 2 x 2 x 2 samples per time-step");
    }
}

std::vector<std::string> residencyChanges(const Series& series, const GpuResidency& residency) {
    std::vector<std::string> changes;
    if (suitsPackedAtlasAt16Bits(series) && residency.requested.precision == DensityPrecision::Bits16 &&
        !residency.storage.packedAtlas)
        changes.push_back("no packed atlas (same image, slower)");
    if (residency.storage.precision != residency.requested.precision)
        changes.push_back(std::to_string(precisionBits(residency.storage.precision)) +
                          "-bit densities (every value is stored exactly)");
    if (residency.scale != 1.0) {
        std::ostringstream coarse;
        coarse.precision(3);
        coarse << "resolution 1/" << residency.scale << " per axis (largest time-step " << dimsText(residency.fullDims)
               << " -> " << dimsText(residency.chosenDims) << ")";
        changes.push_back(coarse.str());
    }
    return changes;
}

std::string residencyText(const Series& series, const GpuMemoryLimits& limits, const GpuResidency& residency) {
    std::ostringstream text;
    text << series.manifestPath.string() << ": GPU memory budget " << byteCountText(double(limits.budgetBytes)) << " ("
         << limits.budgetSource << "): the series needs "
         << (residency.fullBytes ? byteCountText(double(*residency.fullBytes)) : std::string("more than one 3D texture"))
         << " at full size (" << storageText(residency.requested, suitsPackedAtlasAt16Bits(series)) << ")";
    if (!residency.changed()) {
        text << ", which fits";
        return text.str();
    }
    text << "; uploading " << byteCountText(double(residency.chosenBytes)) << ": ";
    const std::vector<std::string> changes = residencyChanges(series, residency);
    for (std::size_t index = 0; index < changes.size(); ++index) text << (index ? ", " : "") << changes[index];
    return text.str();
}

}  // namespace tstyles
