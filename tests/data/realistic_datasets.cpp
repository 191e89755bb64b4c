// Writers of the realistic sample files (realistic_datasets.h): NetCDF through libnetcdf, NIfTI
// through libnifti2. Deterministic: the same bytes on every run.
#include "realistic_datasets.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <netcdf.h>
#include <nifti2_io.h>

namespace tstyles::testdata {
namespace {

void check(int status, const std::string& what) {
    if (status != NC_NOERR) throw std::runtime_error(what + ": " + nc_strerror(status));
}

void putText(int nc, int variable, const char* name, const std::string& text) {
    check(nc_put_att_text(nc, variable, name, text.size(), text.c_str()), name);
}

// A small, fixed pseudo-random jitter in [-1, 1] from a voxel index (no global state).
double jitter(std::size_t index) {
    std::uint32_t x = std::uint32_t(index) * 2654435761u + 12345u;
    x ^= x >> 13;
    x *= 0x5bd1e995u;
    x ^= x >> 15;
    return double(x % 20001u) / 10000.0 - 1.0;
}

struct OceanShape {
    std::size_t times, depths, lats, lons;
    std::vector<double> timeDays, depthMetres, latitudes, longitudes;
};

std::vector<double> evenly(double first, double last, std::size_t count) {
    std::vector<double> values(count);
    for (std::size_t i = 0; i < count; ++i) values[i] = first + (last - first) * double(i) / double(count - 1);
    return values;
}

// Depth levels closer together near the surface, as ocean models have them: 0 .. 1000 m.
std::vector<double> oceanLevels(std::size_t count) {
    std::vector<double> levels(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double f = double(i) / double(count - 1);
        levels[i] = std::round(1000.0 * f * f * 10.0) / 10.0;
    }
    return levels;
}

constexpr float kFill = 1.0e20f;

template <typename Temperature>
void writeOcean(const std::filesystem::path& file, const OceanShape& shape, Temperature temperature) {
    int nc = 0;
    check(nc_create(file.c_str(), NC_NETCDF4 | NC_CLOBBER, &nc), file.string());
    int dims[4] = {};
    check(nc_def_dim(nc, "time", NC_UNLIMITED, &dims[0]), "time");
    check(nc_def_dim(nc, "depth", shape.depths, &dims[1]), "depth");
    check(nc_def_dim(nc, "lat", shape.lats, &dims[2]), "lat");
    check(nc_def_dim(nc, "lon", shape.lons, &dims[3]), "lon");
    int time = 0, depth = 0, lat = 0, lon = 0, thetao = 0;
    check(nc_def_var(nc, "time", NC_DOUBLE, 1, &dims[0], &time), "time var");
    putText(nc, time, "standard_name", "time");
    putText(nc, time, "units", "days since 1950-01-01 00:00:00");
    putText(nc, time, "calendar", "noleap");
    putText(nc, time, "axis", "T");
    check(nc_def_var(nc, "depth", NC_DOUBLE, 1, &dims[1], &depth), "depth var");
    putText(nc, depth, "standard_name", "depth");
    putText(nc, depth, "units", "m");
    putText(nc, depth, "positive", "down");
    putText(nc, depth, "axis", "Z");
    check(nc_def_var(nc, "lat", NC_DOUBLE, 1, &dims[2], &lat), "lat var");
    putText(nc, lat, "standard_name", "latitude");
    putText(nc, lat, "units", "degrees_north");
    putText(nc, lat, "axis", "Y");
    check(nc_def_var(nc, "lon", NC_DOUBLE, 1, &dims[3], &lon), "lon var");
    putText(nc, lon, "standard_name", "longitude");
    putText(nc, lon, "units", "degrees_east");
    putText(nc, lon, "axis", "X");
    check(nc_def_var(nc, "thetao", NC_FLOAT, 4, dims, &thetao), "thetao");
    putText(nc, thetao, "standard_name", "sea_water_potential_temperature");
    putText(nc, thetao, "units", "degC");
    check(nc_put_att_float(nc, thetao, "_FillValue", NC_FLOAT, 1, &kFill), "_FillValue");
    putText(nc, NC_GLOBAL, "Conventions", "CF-1.8");
    check(nc_enddef(nc), "enddef");
    const std::size_t start = 0, count = shape.times;
    check(nc_put_vara_double(nc, time, &start, &count, shape.timeDays.data()), "times");
    check(nc_put_var_double(nc, depth, shape.depthMetres.data()), "depths");
    check(nc_put_var_double(nc, lat, shape.latitudes.data()), "lats");
    check(nc_put_var_double(nc, lon, shape.longitudes.data()), "lons");
    std::vector<float> values(shape.times * shape.depths * shape.lats * shape.lons);
    std::size_t index = 0;
    for (std::size_t t = 0; t < shape.times; ++t)
        for (std::size_t d = 0; d < shape.depths; ++d)
            for (std::size_t y = 0; y < shape.lats; ++y)
                for (std::size_t x = 0; x < shape.lons; ++x, ++index)
                    values[index] = temperature(t, shape.depthMetres[d], shape.latitudes[y], shape.longitudes[x], index);
    const std::size_t starts[4] = {0, 0, 0, 0};
    const std::size_t counts[4] = {shape.times, shape.depths, shape.lats, shape.lons};
    check(nc_put_vara_float(nc, thetao, starts, counts, values.data()), "thetao values");
    check(nc_close(nc), "close");
}

double blob(double dx, double dy, double dz) { return std::exp(-(dx * dx + dy * dy + dz * dz)); }

struct Nifti {
    std::int64_t nx, ny, nz, nt;
    int datatype;
    glm::dvec3 spacing;
    double tr;
};

template <typename Value, typename Fill>
void writeNifti(const std::filesystem::path& file, const Nifti& shape, Fill value) {
    const std::int64_t dims[8] = {shape.nt > 1 ? 4 : 3, shape.nx, shape.ny, shape.nz, shape.nt, 1, 1, 1};
    nifti_image* image = nifti_make_new_nim(dims, shape.datatype, 1);
    if (image == nullptr) throw std::runtime_error("nifti_make_new_nim failed");
    image->dx = image->pixdim[1] = shape.spacing.x;
    image->dy = image->pixdim[2] = shape.spacing.y;
    image->dz = image->pixdim[3] = shape.spacing.z;
    image->dt = image->pixdim[4] = shape.tr;
    image->xyz_units = NIFTI_UNITS_MM;
    image->time_units = NIFTI_UNITS_SEC;
    // RAS+ world, voxel (0,0,0) at the volume's corner so that the centre is the origin.
    image->sform_code = NIFTI_XFORM_SCANNER_ANAT;
    image->sto_xyz = nifti_dmat44{};
    image->sto_xyz.m[0][0] = shape.spacing.x;
    image->sto_xyz.m[1][1] = shape.spacing.y;
    image->sto_xyz.m[2][2] = shape.spacing.z;
    image->sto_xyz.m[0][3] = -0.5 * shape.spacing.x * double(shape.nx - 1);
    image->sto_xyz.m[1][3] = -0.5 * shape.spacing.y * double(shape.ny - 1);
    image->sto_xyz.m[2][3] = -0.5 * shape.spacing.z * double(shape.nz - 1);
    image->sto_xyz.m[3][3] = 1.0;
    image->sto_ijk = nifti_dmat44_inverse(image->sto_xyz);
    auto* values = static_cast<Value*>(image->data);
    std::size_t index = 0;
    for (std::int64_t t = 0; t < shape.nt; ++t)
        for (std::int64_t z = 0; z < shape.nz; ++z)
            for (std::int64_t y = 0; y < shape.ny; ++y)
                for (std::int64_t x = 0; x < shape.nx; ++x, ++index) values[index] = value(int(x), int(y), int(z), int(t), index);
    if (nifti_set_filenames(image, file.c_str(), 0, 1) != 0) throw std::runtime_error("nifti_set_filenames failed");
    nifti_image_write(image);
    nifti_image_free(image);
}

}  // namespace

void writeOceanAnomalies(const std::filesystem::path& file) {
    OceanShape shape{3, 12, 30, 40, {6939.0 + 14.0, 6939.0 + 45.0, 6939.0 + 73.0}, oceanLevels(12),
                     evenly(30.0, 45.0, 30), evenly(-40.0, -20.0, 40)};
    // 6935 days (19 years of 365) after 1950-01-01 on the noleap calendar is 1969-01-01: 1969-01-19, ...
    writeOcean(file, shape, [](std::size_t t, double depth, double lat, double lon, std::size_t index) {
        if (lon > -25.0 && lat < 34.0) return kFill;  // land in the south-east
        double anomaly = 0.0;
        if (t == 0) anomaly = 5.0 * blob((lon + 37.0) / 2.0, (lat - 42.0) / 1.5, depth / 80.0);  // north-west, surface
        if (t == 1) anomaly = 5.0 * blob((lon + 30.0) / 2.0, (lat - 37.5) / 1.5, (depth - 300.0) / 100.0);
        if (t == 2) anomaly = 5.0 * blob((lon + 35.0) / 2.0, (lat - 32.0) / 1.5, (depth - 900.0) / 100.0);
        return float(4.0 + anomaly + 0.01 * jitter(index));
    });
}

void writeOceanEddy(const std::filesystem::path& file) {
    std::vector<double> months;
    const double monthStarts[6] = {0, 31, 59, 90, 120, 151};
    for (double start : monthStarts) months.push_back(21900.0 + start + 14.0);  // 2010 on the noleap calendar
    OceanShape shape{6, 20, 60, 80, months, oceanLevels(20), evenly(25.0, 45.0, 60), evenly(-70.0, -40.0, 80)};
    writeOcean(file, shape, [](std::size_t t, double depth, double lat, double lon, std::size_t index) {
        if (lon < -62.0 + 0.4 * (lat - 25.0) && lat > 33.0) return kFill;  // a coast in the north-west
        if (depth > 900.0 - 8.0 * (lon + 70.0) && lon < -55.0) return kFill;  // the continental slope
        // Spring warms the surface month by month.
        const double thermocline = 4.0 + 18.0 * std::exp(-depth / 250.0) * (1.0 - 0.02 * (lat - 25.0)) +
                                   0.6 * double(t) * std::exp(-depth / 60.0);
        const double eddyLon = -64.0 + 4.0 * double(t);
        const double eddy = 6.0 * blob((lon - eddyLon) / 2.5, (lat - 36.0) / 2.0, depth / 450.0);
        return float(thermocline + eddy + 0.05 * jitter(index));
    });
}

void writeMovingBlobNifti(const std::filesystem::path& file) {
    writeNifti<float>(file, {56, 40, 36, 4, DT_FLOAT32, {3.0, 3.0, 3.0}, 2.0},
                      [](int x, int y, int z, int t, std::size_t) {
                          const double dx = x - (10.0 + 12.0 * t), dy = y - 20.0, dz = z - 18.0;
                          return dx * dx + dy * dy + dz * dz <= 16.0 ? 100.0f : 0.0f;
                      });
}

void writeCtPhantom(const std::filesystem::path& file) {
    writeNifti<std::int16_t>(file, {96, 96, 64, 3, DT_INT16, {0.8, 0.8, 1.5}, 60.0},
                             [](int x, int y, int z, int t, std::size_t index) {
                                 const double bx = (x - 47.5) / 40.0, by = (y - 47.5) / 30.0;
                                 if (bx * bx + by * by > 1.0 || z < 4 || z > 59)
                                     return std::int16_t(-1000 + 8.0 * jitter(index));
                                 // Subcutaneous fat (-100 HU) in the outer sixth of the body.
                                 if (bx * bx + by * by > 0.7) return std::int16_t(-100 + 10.0 * jitter(index));
                                 const double sx = (x - 47.5) / 6.0, sy = (y - 27.0) / 6.0;
                                 if (sx * sx + sy * sy <= 1.0) return std::int16_t(700 + 20.0 * jitter(index));
                                 const double lx = (x - 62.0), ly = (y - 55.0), lz = (z - 32.0);
                                 const double radius = 4.0 + 3.0 * t;
                                 if (lx * lx + ly * ly + lz * lz <= radius * radius)
                                     return std::int16_t(120 + 10.0 * jitter(index));
                                 return std::int16_t(40 + 10.0 * jitter(index));
                             });
}

}  // namespace tstyles::testdata
