// Writers of the realistic sample files (realistic_datasets.h): NetCDF through libnetcdf, NIfTI
// through libnifti2. Deterministic: the same bytes on every run.
#include "realistic_datasets.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
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

// An approximately Gaussian value of mean 0 and standard deviation 1 from a voxel index: four
// jitters summed (deterministic, no global state).
double gaussian(std::size_t index) {
    double sum = 0.0;
    for (std::size_t k = 0; k < 4; ++k) sum += jitter(4 * index + k + 7919);
    return sum / std::sqrt(4.0 / 3.0);
}

// One CF coordinate: name, values and text attributes.
struct CfCoordinate {
    std::string name;
    std::vector<double> values;
    std::vector<std::pair<std::string, std::string>> attributes;
};

// A CF NetCDF-4 file of one float variable(time, level, y, x) with _FillValue 1e20.
struct CfVolume {
    std::string variable;
    std::vector<std::pair<std::string, std::string>> attributes;  // of the variable
    CfCoordinate time, level, y, x;
    std::optional<std::vector<double>> climatologyBounds;  // 2 per time-step: the time's `climatology`
};

template <typename Value>
void writeCfVolume(const std::filesystem::path& file, const CfVolume& spec, Value value) {
    int nc = 0;
    check(nc_create(file.c_str(), NC_NETCDF4 | NC_CLOBBER, &nc), file.string());
    const CfCoordinate* coordinates[4] = {&spec.time, &spec.level, &spec.y, &spec.x};
    int dims[4] = {}, variables[4] = {};
    for (int axis = 0; axis < 4; ++axis) {
        const CfCoordinate& coordinate = *coordinates[axis];
        check(nc_def_dim(nc, coordinate.name.c_str(), axis == 0 ? NC_UNLIMITED : coordinate.values.size(), &dims[axis]),
              coordinate.name);
        check(nc_def_var(nc, coordinate.name.c_str(), NC_DOUBLE, 1, &dims[axis], &variables[axis]), coordinate.name);
        for (const auto& [name, text] : coordinate.attributes) putText(nc, variables[axis], name.c_str(), text);
    }
    int bounds = 0;
    if (spec.climatologyBounds) {
        int pair = 0;
        check(nc_def_dim(nc, "nbounds", 2, &pair), "nbounds");
        const int boundDims[2] = {dims[0], pair};
        check(nc_def_var(nc, "climatology_bounds", NC_DOUBLE, 2, boundDims, &bounds), "climatology_bounds");
        putText(nc, variables[0], "climatology", "climatology_bounds");
    }
    int data = 0;
    check(nc_def_var(nc, spec.variable.c_str(), NC_FLOAT, 4, dims, &data), spec.variable);
    for (const auto& [name, text] : spec.attributes) putText(nc, data, name.c_str(), text);
    check(nc_put_att_float(nc, data, "_FillValue", NC_FLOAT, 1, &kFill), "_FillValue");
    putText(nc, NC_GLOBAL, "Conventions", "CF-1.8");
    check(nc_enddef(nc), "enddef");
    for (int axis = 0; axis < 4; ++axis) {
        const std::size_t start = 0, count = coordinates[axis]->values.size();
        check(nc_put_vara_double(nc, variables[axis], &start, &count, coordinates[axis]->values.data()),
              coordinates[axis]->name + " values");
    }
    if (spec.climatologyBounds) {
        const std::size_t starts[2] = {0, 0}, counts[2] = {spec.time.values.size(), 2};
        check(nc_put_vara_double(nc, bounds, starts, counts, spec.climatologyBounds->data()), "climatology bounds");
    }
    const std::size_t nt = spec.time.values.size(), nz = spec.level.values.size(), ny = spec.y.values.size(),
                      nx = spec.x.values.size();
    std::vector<float> values(nt * nz * ny * nx);
    std::size_t index = 0;
    for (std::size_t t = 0; t < nt; ++t)
        for (std::size_t z = 0; z < nz; ++z)
            for (std::size_t y = 0; y < ny; ++y)
                for (std::size_t x = 0; x < nx; ++x, ++index)
                    values[index] = value(t, spec.level.values[z], spec.y.values[y], spec.x.values[x], index);
    const std::size_t starts[4] = {0, 0, 0, 0};
    const std::size_t counts[4] = {nt, nz, ny, nx};
    check(nc_put_vara_float(nc, data, starts, counts, values.data()), spec.variable + " values");
    check(nc_close(nc), "close");
}

// Whether (lon, lat) lies in an ellipse centred on (lon0, lat0) with these radii in degrees,
// grown by `grow` (a share of the radii).
bool inEllipse(double lon, double lat, double lon0, double lat0, double radiusLon, double radiusLat, double grow) {
    const double u = (lon - lon0) / (radiusLon * (1.0 + grow)), v = (lat - lat0) / (radiusLat * (1.0 + grow));
    return u * u + v * v <= 1.0;
}

// Rough continents (ellipses in degrees), and shelves that widen with depth: land at a place and depth.
bool isLand(double lon, double lat, double depthMetres) {
    const double grow = 0.12 * depthMetres / 1000.0;
    return lat < -70.0 + 4.0 * grow ||                                   // Antarctica
           inEllipse(lon, lat, -100.0, 48.0, 28.0, 18.0, grow) ||         // North America
           inEllipse(lon, lat, -88.0, 20.0, 8.0, 9.0, grow) ||            // Central America
           inEllipse(lon, lat, -60.0, -15.0, 16.0, 27.0, grow) ||         // South America
           inEllipse(lon, lat, -41.0, 73.0, 12.0, 9.0, grow) ||           // Greenland
           inEllipse(lon, lat, 20.0, 5.0, 19.0, 30.0, grow) ||            // Africa
           inEllipse(lon, lat, 90.0, 50.0, 75.0, 20.0, grow) ||           // Eurasia
           inEllipse(lon, lat, 78.0, 20.0, 10.0, 12.0, grow) ||           // India
           inEllipse(lon, lat, 134.0, -25.0, 16.0, 10.0, grow);           // Australia
}

}  // namespace

void writeOceanClimatology(const std::filesystem::path& file) {
    CfVolume spec;
    spec.variable = "t_an";
    spec.attributes = {{"standard_name", "sea_water_temperature"},
                       {"long_name", "Objectively analyzed mean fields for sea_water_temperature at standard depth "
                                     "levels."},
                       {"units", "degrees_celsius"}};
    std::vector<double> months, bounds;
    for (int month = 0; month < 12; ++month) {
        months.push_back(month + 0.5);
        bounds.push_back(month);
        bounds.push_back(month + 1.0);
    }
    spec.time = {"time", months, {{"standard_name", "time"}, {"units", "months since 0000-01-01 00:00:00"},
                                  {"axis", "T"}}};
    spec.climatologyBounds = bounds;
    spec.level = {"depth",
                  {0, 10, 20, 30, 50, 75, 100, 125, 150, 200, 250, 300, 400, 500, 600, 700, 800, 900, 1000},
                  {{"standard_name", "depth"}, {"units", "meters"}, {"positive", "down"}, {"axis", "Z"}}};
    spec.y = {"lat", evenly(-88.0, 88.0, 45), {{"standard_name", "latitude"}, {"units", "degrees_north"}}};
    spec.x = {"lon", evenly(-178.0, 178.0, 90), {{"standard_name", "longitude"}, {"units", "degrees_east"}}};
    writeCfVolume(file, spec, [](std::size_t t, double depth, double lat, double lon, std::size_t index) {
        if (isLand(lon, lat, depth)) return kFill;
        const double coslat = std::cos(lat * M_PI / 180.0);
        const double surface = -1.0 + 29.0 * coslat * coslat;
        const double deep = 2.0 + 2.0 * coslat * coslat;
        // The north's surface is warmest in August (month 7.5 of 12), the south's in February; the
        // season reaches down through the mixed layer late and weak: a month later for every 40 m,
        // its amplitude e-folding over 80 m.
        const double peakMonth = 7.5 + depth / 40.0;
        const double season = 3.0 * std::sin(std::abs(lat) * M_PI / 180.0) * (lat >= 0.0 ? 1.0 : -1.0) *
                               std::cos(2.0 * M_PI * (double(t) + 0.5 - peakMonth) / 12.0) * std::exp(-depth / 80.0);
        return float(deep + (surface - deep) * std::exp(-depth / 300.0) + season + 0.01 * jitter(index));
    });
}

void writeRegionalForecast(const std::filesystem::path& file) {
    CfVolume spec;
    spec.variable = "clwc";
    spec.attributes = {{"standard_name", "specific_cloud_liquid_water_content"},
                       {"long_name", "Specific cloud liquid water content"},
                       {"units", "kg kg**-1"}};
    spec.time = {"time", {0, 6, 12, 18, 24, 30, 36}, {{"standard_name", "time"},
                                                      {"units", "hours since 2026-11-28 00:00:00"},
                                                      {"calendar", "gregorian"}}};
    spec.level = {"level", evenly(1000.0, 300.0, 10), {{"standard_name", "air_pressure"}, {"units", "millibars"},
                                                       {"positive", "down"}}};
    spec.y = {"latitude", evenly(50.0, 30.0, 81), {{"standard_name", "latitude"}, {"units", "degrees_north"}}};
    spec.x = {"longitude", evenly(-110.0, -80.0, 121), {{"standard_name", "longitude"}, {"units", "degrees_east"}}};
    writeCfVolume(file, spec, [](std::size_t t, double pressure, double lat, double lon, std::size_t index) {
        // Cloud between 900 and 500 hPa.
        const double layer = std::exp(-std::pow((pressure - 700.0) / 150.0, 2.0));
        // The front: a band from south-west to north-east that moves 2 degrees east every 6 hours and deepens.
        const double frontLon = -104.0 + 2.0 * double(t) + 0.5 * (lat - 40.0);
        const double front = (0.4 + 0.1 * double(t)) * std::exp(-std::pow((lon - frontLon) / 1.2, 2.0));
        // The mountain cloud in the north-west: the same at every step.
        const double mountain = 0.5 * blob((lon + 107.0) / 1.5, (lat - 46.0) / 1.5, 0.0);
        const double cloud = 1.0e-4 * layer * (front + mountain);
        return float(cloud < 2.0e-6 ? 0.0 : cloud * (1.0 + 0.02 * jitter(index)));
    });
}

void writeFmriRun(const std::filesystem::path& file) {
    writeNifti<std::int16_t>(file, {64, 64, 30, 40, DT_INT16, {3.5, 3.5, 4.0}, 2.0},
                             [](int x, int y, int z, int t, std::size_t index) {
                                 const double bx = (x - 31.5) / 24.0, by = (y - 31.5) / 28.0, bz = (z - 14.0) / 14.0;
                                 const double r = bx * bx + by * by + bz * bz;
                                 if (r > 1.0) return std::int16_t(std::lround(20.0 + 3.0 * gaussian(index)));
                                 // Grey matter outside, white inside.
                                 double signal = r > 0.6 ? 560.0 : 640.0;
                                 const bool on = (t / 10) % 2 == 1;
                                 const double visual = blob((x - 31.5) / 3.0, (y - 7.0) / 3.0, (z - 14.0) / 3.0);
                                 const double motor = blob((x - 20.0) / 3.0, (y - 34.0) / 3.0, (z - 24.0) / 3.0);
                                 if (on) signal *= 1.0 + 0.03 * std::max(visual, motor);
                                 return std::int16_t(std::lround(signal + 6.0 * gaussian(index)));
                             });
}

void writeBrainFollowUp(const std::filesystem::path& file) {
    writeNifti<std::int16_t>(file, {80, 96, 72, 2, DT_INT16, {2.0, 2.0, 2.0}, 1.0},
                             [](int x, int y, int z, int t, std::size_t index) {
                                 const double bx = (x - 39.5) / 32.0, by = (y - 47.5) / 40.0, bz = (z - 34.0) / 30.0;
                                 const double r = bx * bx + by * by + bz * bz;
                                 if (r > 1.0) return std::int16_t(std::lround(10.0 + 4.0 * gaussian(index)));
                                 double signal = r > 0.65 ? 600.0 : 800.0;
                                 const double vx = (x - 39.5) / 5.0, vy = (y - 50.0) / 14.0, vz = (z - 38.0) / 6.0;
                                 if (std::abs(x - 39.5) > 2.0 && vx * vx + vy * vy + vz * vz <= 1.0) signal = 250.0;
                                 const double radius = t == 0 ? 5.0 : 7.0;
                                 const double lx = x - 56.0, ly = y - 62.0, lz = z - 44.0;
                                 if (lx * lx + ly * ly + lz * lz <= radius * radius) signal = 1100.0;
                                 return std::int16_t(std::lround(signal * (1.0 + 0.02 * gaussian(index))));
                             });
}

void writeCtHeadPerfusion(const std::filesystem::path& file) {
    writeNifti<std::int16_t>(file, {96, 96, 48, 4, DT_INT16, {2.0, 2.0, 3.0}, 4.0},
                             [](int x, int y, int z, int t, std::size_t index) {
                                 const double hx = (x - 47.5) / 38.0, hy = (y - 47.5) / 44.0, hz = (z - 20.0) / 26.0;
                                 const double r = std::sqrt(hx * hx + hy * hy + hz * hz);
                                 const double noise = 6.0 * gaussian(index);
                                 if (r > 1.0 || z < 2) return std::int16_t(std::lround(-1000.0 + noise));
                                 if (r > 0.9) return std::int16_t(std::lround(1200.0 + 3.0 * noise));  // skull
                                 // Contrast in three arteries (vertical tubes), peaking at the third time-step.
                                 const double bolus[4] = {0.0, 0.45, 1.0, 0.6};
                                 for (const double ax : {40.0, 56.0, 47.5}) {
                                     const double ay = ax == 47.5 ? 30.0 : 58.0;
                                     if ((x - ax) * (x - ax) + (y - ay) * (y - ay) <= 4.0)
                                         return std::int16_t(std::lround(40.0 + 280.0 * bolus[t] + noise));
                                 }
                                 const double vx = (x - 47.5) / 8.0, vy = (y - 50.0) / 14.0, vz = (z - 24.0) / 6.0;
                                 if (std::abs(x - 47.5) > 1.5 && vx * vx + vy * vy + vz * vz <= 1.0)
                                     return std::int16_t(std::lround(8.0 + noise));  // ventricles
                                 // The right hemisphere (+x in RAS) enhances with the bolus.
                                 const double enhancement = x > 47.5 ? 15.0 * bolus[t] : 0.0;
                                 return std::int16_t(std::lround(35.0 + enhancement + noise));
                             });
}

void writeMrSlab(const std::filesystem::path& file) {
    writeNifti<std::int16_t>(file, {128, 128, 24, 3, DT_INT16, {2.0, 2.0, 2.2}, 60.0},
                             [](int x, int y, int z, int t, std::size_t index) {
                                 // An axial slab through the ventricles: the head a little longer
                                 // front to back (y, anterior), narrowing away from the middle slice.
                                 const double narrowing = std::sqrt(1.0 - std::pow((z - 11.5) / 40.0, 2.0));
                                 const double hx = (x - 63.5) / (54.0 * narrowing), hy = (y - 63.5) / (62.0 * narrowing);
                                 const double r = std::sqrt(hx * hx + hy * hy);
                                 const double noise = gaussian(index);
                                 if (r > 1.0) return std::int16_t(std::lround(std::abs(6.0 * noise)));
                                 if (r > 0.93) return std::int16_t(std::lround(900.0 + 30.0 * noise));  // scalp fat
                                 if (r > 0.88) return std::int16_t(std::lround(60.0 + 10.0 * noise));   // skull
                                 double signal = r > 0.75 ? 620.0 : 760.0;  // grey matter outside, white inside
                                 // The lateral ventricles: two crescents either side of the midline, dark.
                                 for (const double side : {-1.0, 1.0}) {
                                     const double vx = (x - 63.5 - side * 9.0) / 6.0, vy = (y - 66.0) / 22.0;
                                     if (vx * vx + vy * vy <= 1.0) signal = 180.0;
                                 }
                                 // An enhancing lesion in the right frontal lobe (RAS: +x right, +y anterior).
                                 const double lx = (x - 84.0) / 7.0, ly = (y - 92.0) / 7.0;
                                 const double contrast[3] = {0.0, 0.7, 1.0};
                                 if (lx * lx + ly * ly <= 1.0 && std::abs(z - 12.0) <= 5.0)
                                     signal = 700.0 + 600.0 * contrast[t];
                                 return std::int16_t(std::lround(signal * (1.0 + 0.02 * noise)));
                             });
}

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
