// The series transfer (src/data/series_transfer.h): a series of every grid kind written to a memfd
// comes back the same to the bit; the writer lets go of its values as it writes, the reader gives
// the shared memory back as it reads, and a cut stream is an error, not a series.
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "series_equality.h"
#include "series_transfer.h"

namespace tstyles {
namespace {

class SharedMemory {
public:
    SharedMemory() : fd_(memfd_create("series_transfer_test", MFD_CLOEXEC)) {}
    ~SharedMemory() { close(fd_); }
    int fd() const { return fd_; }
    std::uint64_t allocatedBytes() const {
        struct stat info {};
        fstat(fd_, &info);
        return std::uint64_t(info.st_blocks) * 512;
    }

private:
    int fd_;
};

std::vector<float> ramp(std::size_t count, float start) {
    std::vector<float> values(count);
    for (std::size_t index = 0; index < count; ++index) values[index] = start + float(index) / 7.0f;
    return values;
}

Series everyKindOfStep() {
    Series series;
    series.name = "every kind";
    series.manifestPath = "/data/series.json";
    series.valueRange = {-1.5, 3.25};
    series.valueUnit = "m s-1";
    series.precision = DensityPrecision::Bits32;
    series.sourceFormat = "NetCDF-4";
    series.readingNotes = {"variable temp", "time from the time variable"};
    series.axes = {SpatialAxis{"lon", "degrees_east", AxisDirection::East},
                   SpatialAxis{"lat", "degrees_north", AxisDirection::North}, SpatialAxis{"pressure", "hPa", AxisDirection::Up, true}};
    series.time.unit = TimeUnit::Hours;
    series.time.reference = CalendarDate{2005, 8, 28, 6, 30, 12.5};
    series.time.calendar = Calendar::NoLeap;
    series.time.climatology = true;

    TimeStep rectilinear;
    rectilinear.time = 0.25;
    RectilinearGrid grid;
    grid.dims = {4, 3, 2};
    grid.spacing = {0.5, 2.0, 1.0};
    grid.axisPositions[2] = {0.0, 7.5};
    rectilinear.grid = grid;
    rectilinear.placement.origin = {1.0, -2.0, 3.0};
    rectilinear.placement.rotation = glm::dquat(0.5, 0.5, 0.5, 0.5);
    rectilinear.sourceType = ValueType::Int16;
    rectilinear.rawRange = {-3.0, 9.0};
    rectilinear.density = ramp(24, 0.0f);
    rectilinear.density[3] = missingDensity();
    rectilinear.density[5] = -0.0f;
    rectilinear.mask = std::vector<std::uint8_t>(24, 1);
    rectilinear.valuesFile = "values_0.raw";
    rectilinear.maskFile = "mask_0.raw";
    series.steps.push_back(rectilinear);

    auto nodes = std::make_shared<const std::vector<glm::vec3>>(8, glm::vec3(1.0f, 2.0f, 3.0f));
    for (int index = 0; index < 2; ++index) {
        TimeStep structured;
        structured.time = 1.0 + index;
        structured.grid = makeStructuredGrid({2, 2, 2}, nodes, "grid.xyz");
        structured.density = ramp(8, float(index));
        series.steps.push_back(structured);
    }

    TimeStep beam;
    beam.time = 4.0;
    BeamGrid fan;
    fan.dims = {2, 2, 3};
    fan.azimuthDeg = {-10.0, 10.0};
    fan.elevationDeg = {-5.0, 5.0};
    fan.minRange = 1.0;
    fan.maxRange = 9.0;
    beam.grid = fan;
    beam.density = ramp(12, 2.0f);
    series.steps.push_back(beam);
    return series;
}

TEST(SeriesTransfer, EveryFieldComesBackToTheBit) {
    const Series original = everyKindOfStep();
    SharedMemory memory;
    Series sent = original;
    const std::uint64_t bytes = writeSeries(memory.fd(), std::move(sent));
    for (const TimeStep& step : sent.steps) {  // NOLINT(bugprone-use-after-move): the writer empties it
        EXPECT_TRUE(step.density.empty());
        EXPECT_FALSE(step.mask.has_value());
    }
    const Series received = readSeries(memory.fd(), bytes);
    tstyles_test::expectSameSeries(original, received);
    // Steps that shared one node array still do.
    EXPECT_EQ(received.steps[1].structured()->nodes, received.steps[2].structured()->nodes);
}

TEST(SeriesTransfer, ReadingGivesTheSharedMemoryBack) {
    Series series;
    TimeStep step;
    RectilinearGrid grid;
    grid.dims = {64, 64, 64};
    step.grid = grid;
    step.density = ramp(grid.voxelCount(), 0.0f);
    series.steps.assign(4, step);
    SharedMemory memory;
    const std::uint64_t bytes = writeSeries(memory.fd(), std::move(series));
    EXPECT_GE(memory.allocatedBytes(), 4u * 64 * 64 * 64 * sizeof(float));
    const Series received = readSeries(memory.fd(), bytes);
    ASSERT_EQ(received.size(), 4u);
    // Only the pages that straddle a value array's ends remain.
    EXPECT_LT(memory.allocatedBytes(), std::uint64_t(64) * 1024);
}

TEST(SeriesTransfer, ACutStreamIsAnErrorNotASeries) {
    SharedMemory memory;
    const std::uint64_t bytes = writeSeries(memory.fd(), everyKindOfStep());
    for (std::uint64_t cut : {std::uint64_t(0), std::uint64_t(5), bytes / 2, bytes - 1})
        EXPECT_THROW(readSeries(memory.fd(), cut), std::runtime_error) << "cut at " << cut;
}

}  // namespace
}  // namespace tstyles
