// libnifti2 reads the header and one volume at a time; we only translate its fields.
#include "nifti_reader.h"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <cstring>
#include <memory>

#include <nifti2_io.h>
#include <zlib.h>

#include "../../value_decoding.h"
#include "../infinite_values.h"
#include "../oriented_axes.h"
#include "../file_bytes.h"
#include "../series_assembly.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/stderr_capture.h"

namespace tstyles {
namespace {

struct NiftiFree {
    void operator()(nifti_image* image) const { nifti_image_free(image); }
};
using NiftiImage = std::unique_ptr<nifti_image, NiftiFree>;

struct MallocFree {
    void operator()(void* data) const { std::free(data); }
};

ValueType niftiValueType(const nifti_image& image, const std::filesystem::path& file) {
    switch (image.datatype) {
        case DT_UINT8:
            return ValueType::UInt8;
        case DT_INT8:
            return ValueType::Int8;
        case DT_INT16:
            return ValueType::Int16;
        case DT_UINT16:
            return ValueType::UInt16;
        case DT_INT32:
            return ValueType::Int32;
        case DT_FLOAT32:
            return ValueType::Float32;
        case DT_FLOAT64:
            return ValueType::Float64;
        default:
            throwInputError(file, "datatype",
                            std::string("unsupported voxel type ") + nifti_datatype_string(image.datatype) +
                                " (supported: INT8, UINT8, INT16, UINT16, INT32, FLOAT32, FLOAT64)");
    }
}

// sform if set, else qform, else the voxel sizes alone (method 1 of the NIfTI-1 standard).
OrientedAxes niftiFrame(const nifti_image& image, const glm::ivec3& dims, const std::filesystem::path& file) {
    const nifti_dmat44* matrix = image.sform_code > 0 ? &image.sto_xyz : image.qform_code > 0 ? &image.qto_xyz : nullptr;
    if (matrix == nullptr) {
        const glm::dvec3 spacing{std::abs(image.dx), std::abs(image.dy), std::abs(image.dz)};
        std::array<glm::dvec3, 3> axes{glm::dvec3(spacing.x > 0 ? spacing.x : 1.0, 0, 0),
                                       glm::dvec3(0, spacing.y > 0 ? spacing.y : 1.0, 0),
                                       glm::dvec3(0, 0, spacing.z > 0 ? spacing.z : 1.0)};
        return orientAxes(glm::dvec3(0.0), axes, dims, file, "pixdim");
    }
    std::array<glm::dvec3, 3> axes{};
    for (int column = 0; column < 3; ++column)
        axes[std::size_t(column)] = {matrix->m[0][column], matrix->m[1][column], matrix->m[2][column]};
    const glm::dvec3 origin{matrix->m[0][3], matrix->m[1][3], matrix->m[2][3]};
    return orientAxes(origin, axes, dims, file, image.sform_code > 0 ? "sform" : "qform");
}

// With an sform or qform the world is RAS+ (x toward the patient's right, y anterior, z superior);
// without either, nothing is known of the orientation. Units from xyzt_units.
std::array<SpatialAxis, 3> niftiAxes(const nifti_image& image) {
    const bool oriented = image.sform_code > 0 || image.qform_code > 0;
    const std::string unit = image.xyz_units == NIFTI_UNITS_MM       ? "mm"
                             : image.xyz_units == NIFTI_UNITS_METER  ? "m"
                             : image.xyz_units == NIFTI_UNITS_MICRON ? "um"
                                                                     : "";
    const AxisDirection directions[3] = {AxisDirection::Right, AxisDirection::Anterior, AxisDirection::Superior};
    std::array<SpatialAxis, 3> axes;
    for (int axis = 0; axis < 3; ++axis)
        axes[std::size_t(axis)] = {std::string(1, char('x' + axis)), unit,
                                   oriented ? directions[axis] : AxisDirection::Unknown};
    return axes;
}

NiftiImage readHeader(const std::filesystem::path& file) {
    requireRegularFile(file, "NIfTI file");
    nifti_set_debug_level(0);  // its messages would go to stderr; ours say what went wrong
    // Some of its complaints are printed whatever the debug level: captured, quoted in ours.
    const StderrCapture libraryMessages;
    NiftiImage image(nifti_image_read(file.c_str(), 0));
    if (!image) {
        const std::string said = libraryMessages.text();
        throwInputError(file, "", "not a readable NIfTI-1 or NIfTI-2 image (bad or truncated header)" +
                                      (said.empty() ? std::string() : ": " + said));
    }
    return image;
}

// The voxel data must be in the file before anything is allocated for it: every byte of an
// uncompressed file, enough compressed bytes in a gzip one (the rest is checked on inflating).
void requireVoxelData(const nifti_image& image, const std::filesystem::path& dataFile) {
    const double dataBytes = double(image.nvox) * double(image.nbyper);
    const std::uint64_t offset = std::uint64_t(std::max<std::int64_t>(0, image.iname_offset));
    if (nifti_is_gzfile(dataFile.c_str()) != 0)
        return requireDataInFile(dataFile, offset, dataBytes, DataEncoding::Gzip, "the NIfTI voxel data");
    const std::uint64_t size = regularFileSize(dataFile, "NIfTI data file");
    if (double(size) < double(offset) + dataBytes)
        throwInputError(dataFile, "",
                        "is truncated: the header asks for " + std::to_string(std::uint64_t(dataBytes)) +
                            " bytes of voxel data from byte " + std::to_string(offset) + ", the file has " +
                            std::to_string(size) + " bytes");
}

}  // namespace

SourceSeries openNifti(const std::filesystem::path& file) {
    std::shared_ptr<nifti_image> image(readHeader(file).release(), NiftiFree{});
    if (image->ndim < 3 || image->nx < 2 || image->ny < 2 || image->nz < 2)
        throwInputError(file, "dim",
                        "a volume needs at least 2 voxels along x, y and z, found " + std::to_string(image->nx) + " x " +
                            std::to_string(image->ny) + " x " + std::to_string(image->nz));
    if (image->nu > 1 || image->nv > 1 || image->nw > 1)
        throwInputError(file, "dim", "images of more than four dimensions (vector or multi-component) are not supported");
    const ValueType type = niftiValueType(*image, file);
    const glm::ivec3 dims{int(image->nx), int(image->ny), int(image->nz)};
    const OrientedAxes frame = niftiFrame(*image, dims, file);
    const std::size_t stepCount = std::size_t(std::max<std::int64_t>(1, image->nt));
    const double step = image->dt > 0.0 ? image->dt : 1.0;

    const std::filesystem::path dataFile = image->iname ? std::filesystem::path(image->iname) : file;
    requireVoxelData(*image, dataFile);
    requireStepCount(file, "dim[4]", stepCount);

    SourceSeries source;
    source.name = file.filename().string();
    source.file = file;
    source.format = image->nifti_type >= NIFTI_FTYPE_NIFTI2_1 ? "NIfTI-2" : "NIfTI-1";
    source.axes = niftiAxes(*image);
    // xyzt_units: seconds, milliseconds or microseconds; Hz, ppm and rad/s are not times.
    source.time.unit = image->time_units == NIFTI_UNITS_SEC    ? TimeUnit::Seconds
                       : image->time_units == NIFTI_UNITS_MSEC ? TimeUnit::Milliseconds
                       : image->time_units == NIFTI_UNITS_USEC ? TimeUnit::Microseconds
                                                               : TimeUnit::None;
    for (std::size_t index = 0; index < stepCount; ++index) {
        SourceStep timeStep;
        timeStep.time = image->toffset + double(index) * step;
        RectilinearGrid grid;
        grid.dims = dims;
        grid.spacing = frame.spacing;
        timeStep.grid = grid;
        timeStep.placement = frame.placement;
        timeStep.type = type;
        timeStep.file = dataFile;
        source.steps.push_back(timeStep);
    }
    const bool scaled = image->scl_slope != 0.0 && (image->scl_slope != 1.0 || image->scl_inter != 0.0);
    source.readStep = [image, dims, frame, type, scaled, dataFile](std::size_t index) {
        const std::int64_t select[8] = {0, -1, -1, -1, std::int64_t(index), -1, -1, -1};
        void* raw = nullptr;
        const StderrCapture libraryMessages;
        const std::int64_t read = nifti_read_collapsed_image(image.get(), select, &raw);
        std::unique_ptr<void, MallocFree> owned(raw);
        const std::size_t count = std::size_t(dims.x) * std::size_t(dims.y) * std::size_t(dims.z);
        if (read < std::int64_t(count * bytesPerValue(type)) || raw == nullptr) {
            const std::string said = libraryMessages.text();
            throwInputError(dataFile, "",
                            "is truncated or corrupt: cannot read the " + std::to_string(count * bytesPerValue(type)) +
                                " bytes of volume (time-step) " + std::to_string(index) +
                                (said.empty() ? std::string() : " (" + said + ")"));
        }
        // The library has already swapped bytes into the host's order.
        std::vector<float> values(count);
        const auto* bytes = static_cast<const std::uint8_t*>(raw);
        const std::size_t stride = bytesPerValue(type);
        const ByteOrder host = std::endian::native == std::endian::little ? ByteOrder::Little : ByteOrder::Big;
        for (std::size_t voxel = 0; voxel < count; ++voxel) {
            double value = decodeValue(bytes + voxel * stride, type, host);
            if (scaled) value = value * image->scl_slope + image->scl_inter;
            values[voxel] = float(value);
        }
        refuseInfinities(values, dims, dataFile, index);
        if (frame.mirrorX) mirrorAlongX(values, dims);
        return values;
    };
    return source;
}

bool hasNiftiSignature(const std::filesystem::path& file) {
    gzFile stream = gzopen(file.c_str(), "rb");  // reads plain files as they are
    if (stream == nullptr) return false;
    unsigned char header[348] = {};
    const int read = gzread(stream, header, sizeof(header));
    gzclose(stream);
    if (read < 348) return false;
    return std::memcmp(header + 344, "n+1", 4) == 0 || std::memcmp(header + 344, "ni1", 4) == 0 ||
           std::memcmp(header + 4, "n+2", 4) == 0 || std::memcmp(header + 4, "ni2", 4) == 0;
}

}  // namespace tstyles
