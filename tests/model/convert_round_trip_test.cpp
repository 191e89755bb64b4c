// `tstyles convert` at model level: a NetCDF and a NRRD file written here, read raw, written as a
// manifest folder and loaded back give the same densities, times, grids and missing voxels as
// reading the files directly; an existing folder is refused unless overwriting, and nothing is
// left half-written.
#include <cmath>
#include <cstring>
#include <fstream>
#include <utility>

#include <gtest/gtest.h>
#include <netcdf.h>

#include "tstyles/core/errors.h"
#include "tstyles/data/manifest.h"
#include "tstyles/data/series_export.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/data/time_axis.h"

namespace {

std::filesystem::path scratch(const std::string& name) {
    const auto folder = std::filesystem::temp_directory_path() / "tstyles_convert_test" / name;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

void check(int status) {
    ASSERT_EQ(status, NC_NOERR) << nc_strerror(status);
}

// rain(time 2, level 3, y 2, x 3) float, uneven levels 0, 1, 5, a fill value at index 4 of step 1;
// the levels in `levelUnits` where given.
std::filesystem::path writeNetcdf(const std::filesystem::path& folder, const std::string& levelUnits = "") {
    const auto file = folder / "rain.nc";
    int nc = 0, dims[4] = {}, rain = 0, level = 0, time = 0;
    check(nc_create(file.c_str(), NC_CLOBBER, &nc));
    check(nc_def_dim(nc, "time", 2, &dims[0]));
    check(nc_def_dim(nc, "level", 3, &dims[1]));
    check(nc_def_dim(nc, "y", 2, &dims[2]));
    check(nc_def_dim(nc, "x", 3, &dims[3]));
    check(nc_def_var(nc, "time", NC_DOUBLE, 1, &dims[0], &time));
    check(nc_def_var(nc, "level", NC_DOUBLE, 1, &dims[1], &level));
    check(nc_def_var(nc, "rain", NC_FLOAT, 4, dims, &rain));
    const float fill = -1.0f;
    check(nc_put_att_float(nc, rain, "_FillValue", NC_FLOAT, 1, &fill));
    if (!levelUnits.empty()) check(nc_put_att_text(nc, level, "units", levelUnits.size(), levelUnits.c_str()));
    check(nc_enddef(nc));
    const double times[2] = {3, 9}, levels[3] = {0, 1, 5};
    check(nc_put_var_double(nc, time, times));
    check(nc_put_var_double(nc, level, levels));
    std::vector<float> values(36);
    for (std::size_t index = 0; index < values.size(); ++index) values[index] = 0.25f * float(index);
    values[18 + 4] = fill;
    check(nc_put_var_float(nc, rain, values.data()));
    check(nc_close(nc));
    return file;
}

// 3 x 2 x 2 voxels, 2 time-steps, uint16 value = 1000 + 7 * index.
std::filesystem::path writeNrrd(const std::filesystem::path& folder) {
    const auto file = folder / "v.nrrd";
    std::string data;
    for (int index = 0; index < 24; ++index) {
        const int value = 1000 + 7 * index;
        data += char(value & 0xff);
        data += char(value >> 8);
    }
    std::ofstream(file, std::ios::binary)
        << "NRRD0004\ntype: ushort\ndimension: 4\nsizes: 3 2 2 2\nencoding: raw\nendian: little\n"
           "space dimension: 3\nspace directions: (2,0,0) (0,3,0) (0,0,4) none\nspace origin: (1,1,1)\n"
           "kinds: domain domain domain time\n\n"
        << data;
    return file;
}

void expectSameSeries(const tstyles::Series& direct, const tstyles::Series& loaded) {
    ASSERT_EQ(loaded.size(), direct.size());
    EXPECT_EQ(loaded.valueRange, direct.valueRange);
    for (std::size_t step = 0; step < direct.size(); ++step) {
        EXPECT_EQ(loaded.steps[step].time, direct.steps[step].time);
        EXPECT_EQ(loaded.steps[step].rectilinear().dims, direct.steps[step].rectilinear().dims);
        EXPECT_EQ(loaded.steps[step].rectilinear().spacing, direct.steps[step].rectilinear().spacing);
        EXPECT_EQ(loaded.steps[step].rectilinear().axisPositions, direct.steps[step].rectilinear().axisPositions);
        EXPECT_EQ(loaded.steps[step].placement, direct.steps[step].placement);
        ASSERT_EQ(loaded.steps[step].density.size(), direct.steps[step].density.size());
        for (std::size_t voxel = 0; voxel < direct.steps[step].density.size(); ++voxel) {
            const float expected = direct.steps[step].density[voxel];
            const float actual = loaded.steps[step].density[voxel];
            if (tstyles::isMissing(expected)) EXPECT_TRUE(tstyles::isMissing(actual)) << step << " " << voxel;
            else EXPECT_FLOAT_EQ(actual, expected) << "step " << step << " voxel " << voxel;
        }
    }
}

void convert(const std::filesystem::path& input, const std::filesystem::path& output, bool overwrite) {
    const tstyles::Series raw = tstyles::openRawSeries({input}, {});
    tstyles::writeSeriesFolder(tstyles::toRawSeries(raw, input), output, overwrite);
}

TEST(ConvertRoundTrip, NetcdfKeepsValuesTimesUnevenLevelsAndMissingVoxels) {
    const auto folder = scratch("netcdf");
    const auto file = writeNetcdf(folder);
    convert(file, folder / "out", false);
    const tstyles::Series direct = tstyles::openSeries(file, {});
    const tstyles::Series loaded = tstyles::loadSeries(folder / "out");
    expectSameSeries(direct, loaded);
    EXPECT_EQ(loaded.steps[1].time, 9.0);
    EXPECT_EQ(loaded.steps[0].rectilinear().axisPositions[2], (std::vector<double>{0, 1, 5}));
    EXPECT_TRUE(tstyles::isMissing(loaded.steps[1].density[4]));
    // Raw 0.25 * index over [0, 8.75]: index 5 of step 0 is 1.25 / 8.75.
    EXPECT_NEAR(loaded.steps[0].density[5], 1.25 / 8.75, 1e-6);
}

// Pressure levels count down: drawn up, their axis negated, and the manifest keeps that, so that
// `probe --at` of the converted folder takes the levels as the file has them.
TEST(ConvertRoundTrip, NetcdfPressureLevelsStayNegated) {
    const auto folder = scratch("pressure");
    const auto file = writeNetcdf(folder, "hPa");
    convert(file, folder / "out", false);
    const tstyles::Series direct = tstyles::openSeries(file, {});
    const tstyles::Series loaded = tstyles::loadSeries(folder / "out");
    EXPECT_TRUE(direct.axes[2].negated);
    EXPECT_EQ(loaded.axes, direct.axes);
    expectSameSeries(direct, loaded);
    EXPECT_EQ(tstyles::fileBounds(loaded).lower.z, 0.0);
    EXPECT_EQ(tstyles::fileBounds(loaded).upper.z, 5.0);
}

// A CF climatology: twelve monthly means of 1981-2010 stamped mid-month in 1981, the time variable
// naming its bounds in a `climatology` attribute. The flag survives convert; labels name months.
TEST(ConvertRoundTrip, NetcdfClimatologyKeepsItsFlagAndIsLabelledByMonth) {
    const auto folder = scratch("climatology");
    const auto file = folder / "sst_clim.nc";
    int nc = 0, dims[4] = {}, sst = 0, time = 0;
    check(nc_create(file.c_str(), NC_CLOBBER, &nc));
    check(nc_def_dim(nc, "time", 12, &dims[0]));
    check(nc_def_dim(nc, "z", 2, &dims[1]));
    check(nc_def_dim(nc, "y", 2, &dims[2]));
    check(nc_def_dim(nc, "x", 2, &dims[3]));
    check(nc_def_var(nc, "time", NC_DOUBLE, 1, &dims[0], &time));
    for (const auto& [name, text] : {std::pair<const char*, const char*>{"units", "days since 1981-01-01"},
                                     {"calendar", "noleap"}, {"climatology", "climatology_bounds"}})
        check(nc_put_att_text(nc, time, name, std::strlen(text), text));
    check(nc_def_var(nc, "sst", NC_FLOAT, 4, dims, &sst));
    check(nc_enddef(nc));
    const double mid[12] = {15.5, 45, 74.5, 105, 135.5, 166, 196.5, 227.5, 258, 288.5, 319, 349.5};
    check(nc_put_var_double(nc, time, mid));
    std::vector<float> values(96);
    for (std::size_t index = 0; index < values.size(); ++index) values[index] = float(index % 7);
    check(nc_put_var_float(nc, sst, values.data()));
    check(nc_close(nc));

    const tstyles::Series direct = tstyles::openSeries(file, {});
    EXPECT_TRUE(direct.time.climatology);
    convert(file, folder / "out", false);
    const tstyles::Series loaded = tstyles::loadSeries(folder / "out");
    EXPECT_EQ(loaded.time, direct.time);
    std::vector<double> times;
    for (const tstyles::TimeStep& step : loaded.steps) times.push_back(step.time);
    const std::vector<std::string> labels = tstyles::formatTimes(times, loaded.time);
    EXPECT_EQ(labels.front(), "Jan");
    EXPECT_EQ(labels.back(), "Dec");
}

TEST(ConvertRoundTrip, NrrdKeepsValuesSpacingAndOrigin) {
    const auto folder = scratch("nrrd");
    const auto file = writeNrrd(folder);
    convert(file, folder / "out", false);
    const tstyles::Series direct = tstyles::openSeries(file, {});
    const tstyles::Series loaded = tstyles::loadSeries(folder / "out");
    expectSameSeries(direct, loaded);
    EXPECT_EQ(loaded.valueRange[0], 1000.0);
    EXPECT_EQ(loaded.valueRange[1], 1000.0 + 7 * 23);
    EXPECT_EQ(loaded.steps[0].placement.origin, glm::dvec3(1, 1, 1));
}

TEST(ConvertRoundTrip, ANonEmptyFolderIsRefusedUnlessOverwritingAndNothingIsLeftBehind) {
    const auto folder = scratch("refuse");
    const auto file = writeNrrd(folder);
    std::filesystem::create_directories(folder / "out");
    std::ofstream(folder / "out" / "notes.txt") << "keep";
    EXPECT_THROW(convert(file, folder / "out", false), tstyles::InputError);
    EXPECT_TRUE(std::filesystem::exists(folder / "out" / "notes.txt"));
    EXPECT_FALSE(std::filesystem::exists(folder / "out" / "series.json"));

    convert(file, folder / "out", true);
    EXPECT_FALSE(std::filesystem::exists(folder / "out" / "notes.txt"));
    EXPECT_EQ(tstyles::loadSeries(folder / "out").size(), 2u);
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();

    // An empty folder is simply filled.
    std::filesystem::create_directories(folder / "empty");
    convert(file, folder / "empty", false);
    EXPECT_EQ(tstyles::loadSeries(folder / "empty").size(), 2u);
}

}  // namespace
