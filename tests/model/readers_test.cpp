// The readers on files the tests write themselves: NRRD (raw, gzip, 4D), Hurricane Isabel raw
// files (big-endian, 1.0e35 markers), NetCDF (through the C API), and the step selection, value
// range and memory limit every reader shares.
#include <cmath>
#include <cstring>
#include <iterator>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <netcdf.h>
#include <zlib.h>

#include "tstyles/core/errors.h"
#include "tstyles/data/series_opener.h"

namespace {

std::filesystem::path scratch(const std::string& name) {
    const auto folder = std::filesystem::temp_directory_path() / "tstyles_readers_test" / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

void writeBytes(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary) << bytes;
}

std::string bigEndianFloats(const std::vector<float>& values) {
    std::string bytes;
    for (float value : values) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &value, 4);
        for (int shift = 24; shift >= 0; shift -= 8) bytes += char((bits >> shift) & 0xff);
    }
    return bytes;
}

// A 4D NRRD: 3 x 2 x 2 voxels, 2 time-steps, uint8 value = index.
TEST(NrrdReader, FourDimensionalRawIsASeriesAlongTime) {
    const auto folder = scratch("nrrd4d");
    std::string data;
    for (int index = 0; index < 24; ++index) data += char(index);
    writeBytes(folder / "v.nrrd",
               "NRRD0004\ntype: uchar\ndimension: 4\nsizes: 3 2 2 2\nencoding: raw\n"
               "space dimension: 3\nspace directions: (2,0,0) (0,3,0) (0,0,4) none\nspace origin: (1,1,1)\n"
               "kinds: domain domain domain time\n\n" + data);
    const tstyles::Series series = tstyles::openSeries(folder / "v.nrrd", {});
    ASSERT_EQ(series.size(), 2u);
    EXPECT_EQ(series.steps[0].rectilinear().dims, glm::ivec3(3, 2, 2));
    EXPECT_EQ(series.steps[0].rectilinear().spacing, glm::dvec3(2, 3, 4));
    EXPECT_EQ(series.steps[0].placement.origin, glm::dvec3(1, 1, 1));
    EXPECT_EQ(series.valueRange[0], 0.0);
    EXPECT_EQ(series.valueRange[1], 23.0);
    // Second step's first voxel is value 12: density 12 / 23.
    EXPECT_NEAR(series.steps[1].density[0], 12.0 / 23.0, 1e-6);
    EXPECT_NEAR(series.steps[1].density[11], 1.0, 1e-6);
}

TEST(NrrdReader, TruncatedDataIsAnInputError) {
    const auto folder = scratch("nrrdshort");
    writeBytes(folder / "v.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 4 4\nencoding: raw\n\nabc");
    try {
        tstyles::openSeries(folder / "v.nrrd", {});
        FAIL() << "no error";
    } catch (const tstyles::InputError& error) {
        EXPECT_NE(std::string(error.what()).find("truncated"), std::string::npos) << error.what();
    }
}

TEST(NrrdReader, GzipEncodingIsInflated) {
    const auto folder = scratch("nrrdgz");
    std::string data;
    for (int index = 0; index < 8; ++index) data += char(10 * index);
    // A gzip stream written with zlib, appended after the header.
    const auto gzPath = folder / "data.gz";
    gzFile out = gzopen(gzPath.c_str(), "wb");
    gzwrite(out, data.data(), unsigned(data.size()));
    gzclose(out);
    std::ifstream in(gzPath, std::ios::binary);
    const std::string compressed{std::istreambuf_iterator<char>(in), {}};
    writeBytes(folder / "v.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: gzip\n\n" + compressed);
    const tstyles::Series series = tstyles::openSeries(folder / "v.nrrd", {});
    ASSERT_EQ(series.size(), 1u);
    EXPECT_NEAR(series.steps[0].density[7], 1.0, 1e-6);
    EXPECT_NEAR(series.steps[0].density[1], 10.0 / 70.0, 1e-6);
}

// Isabel layout: big-endian float32, x fastest, 1.0e35 for land; hour from the name.
TEST(IsabelReader, MarkersAreMissingAndStepsAreHours) {
    const auto folder = scratch("isabel");
    std::vector<std::filesystem::path> files;
    for (int hour = 1; hour <= 4; ++hour) {
        std::vector<float> values(4 * 4 * 2, float(hour));
        values[0] = 1.0e35f;
        char name[32];
        std::snprintf(name, sizeof(name), "QCLOUDf%02d.bin", hour);
        writeBytes(folder / name, bigEndianFloats(values));
        files.push_back(folder / name);
    }
    tstyles::ReadOptions options;
    options.rawDims = glm::ivec3(4, 4, 2);
    options.steps = tstyles::parseStepSelection("0:4:2", "--steps");
    const tstyles::Series series = tstyles::openSeries(files, options);
    ASSERT_EQ(series.size(), 2u);
    EXPECT_EQ(series.steps[0].time, 1.0);
    EXPECT_EQ(series.steps[1].time, 3.0);
    EXPECT_TRUE(tstyles::isMissing(series.steps[0].density[0]));
    EXPECT_EQ(series.valueRange[0], 1.0);
    EXPECT_EQ(series.valueRange[1], 3.0);
    EXPECT_NEAR(series.steps[1].density[5], 1.0, 1e-6);
}

TEST(IsabelReader, MemoryLimitRefusesWithTheFigureOrFitsByResolution) {
    const auto folder = scratch("isabelmem");
    std::vector<float> values(8 * 8 * 4);
    for (std::size_t index = 0; index < values.size(); ++index) values[index] = float(index);
    writeBytes(folder / "Pf01.bin", bigEndianFloats(values));
    tstyles::ReadOptions options;
    options.rawDims = glm::ivec3(8, 8, 4);
    options.maxMemoryBytes = 1000;  // 256 voxels x 6 bytes = 1536 bytes needed
    try {
        tstyles::openSeries(folder / "Pf01.bin", options);
        FAIL() << "no error";
    } catch (const tstyles::InputError& error) {
        EXPECT_NE(std::string(error.what()).find("needs"), std::string::npos) << error.what();
    }
    options.fit = tstyles::MemoryFit::Resolution;
    const tstyles::Series series = tstyles::openSeries(folder / "Pf01.bin", options);
    const glm::ivec3 dims = series.steps[0].rectilinear().dims;
    EXPECT_LE(double(dims.x * dims.y * dims.z) * 6.0, 1000.0);
    EXPECT_NEAR(series.steps[0].rectilinear().extent().x, 7.0, 1e-9);
}

void check(int status) {
    ASSERT_EQ(status, NC_NOERR) << nc_strerror(status);
}

// A netCDF-4 file: temp(time, depth, lat, lon) with uneven depth, a fill value and packing.
TEST(NetcdfReader, TimeCoordinatesFillValueAndPacking) {
    const auto folder = scratch("netcdf");
    const auto file = folder / "ocean.nc";
    int nc = 0, dims[4] = {}, temp = 0, time = 0, depth = 0;
    check(nc_create(file.c_str(), NC_NETCDF4, &nc));
    check(nc_def_dim(nc, "time", 3, &dims[0]));
    check(nc_def_dim(nc, "depth", 3, &dims[1]));
    check(nc_def_dim(nc, "lat", 2, &dims[2]));
    check(nc_def_dim(nc, "lon", 2, &dims[3]));
    check(nc_def_var(nc, "time", NC_DOUBLE, 1, &dims[0], &time));
    check(nc_put_att_text(nc, time, "units", 24, "hours since 2000-01-01 0"));
    check(nc_def_var(nc, "depth", NC_DOUBLE, 1, &dims[1], &depth));
    check(nc_def_var(nc, "temp", NC_SHORT, 4, dims, &temp));
    const short fill = -999;
    check(nc_put_att_short(nc, temp, "_FillValue", NC_SHORT, 1, &fill));
    const double scale = 0.5, offset = 10.0;
    check(nc_put_att_double(nc, temp, "scale_factor", NC_DOUBLE, 1, &scale));
    check(nc_put_att_double(nc, temp, "add_offset", NC_DOUBLE, 1, &offset));
    check(nc_enddef(nc));
    const double times[3] = {0, 6, 12}, depths[3] = {0, 10, 50};
    check(nc_put_var_double(nc, time, times));
    check(nc_put_var_double(nc, depth, depths));
    std::vector<short> values(36);
    for (std::size_t index = 0; index < values.size(); ++index) values[index] = short(index);
    values[1] = fill;
    check(nc_put_var_short(nc, temp, values.data()));
    check(nc_close(nc));

    const tstyles::Series series = tstyles::openSeries(file, {});
    ASSERT_EQ(series.size(), 3u);
    EXPECT_EQ(series.steps[1].time, 6.0);
    const auto& grid = series.steps[0].rectilinear();
    EXPECT_EQ(grid.dims, glm::ivec3(2, 2, 3));
    ASSERT_TRUE(grid.isUneven(2));
    EXPECT_EQ(grid.axisPositions[2], (std::vector<double>{0, 10, 50}));
    EXPECT_TRUE(tstyles::isMissing(series.steps[0].density[1]));
    // Unpacked: 10 + 0.5 * stored; the range runs over stored 0..35 without the fill.
    EXPECT_DOUBLE_EQ(series.valueRange[0], 10.0);
    EXPECT_DOUBLE_EQ(series.valueRange[1], 27.5);

    tstyles::ReadOptions missingVariable;
    missingVariable.variable = "salt";
    EXPECT_THROW(tstyles::openSeries(file, missingVariable), tstyles::InputError);
}

TEST(SeriesOpener, UnknownFormatIsAnInputError) {
    const auto folder = scratch("unknown");
    writeBytes(folder / "thing.xyz", "hello");
    EXPECT_THROW(tstyles::openSeries(folder / "thing.xyz", {}), tstyles::InputError);
}

}  // namespace
