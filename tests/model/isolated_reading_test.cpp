// The isolated reading (tstyles/data/isolated_reading.h): a reader that crashes, hangs or allocates
// without bound is caught as one InputError naming the library and the stage, with nothing left
// behind; errors come back as they were; and every dataset we can make reads back the same to the bit
// as in-process (the bundled ones, CF NetCDF-4, NIfTI, and every sample of the readers' CLI test).
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <new>
#include <thread>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../data/realistic_datasets.h"
#include "series_equality.h"
#include "test_dataset.h"
#include "tstyles/core/bundled_data.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/isolated_reading.h"
#include "tstyles/data/series_opener.h"

#if defined(__SANITIZE_ADDRESS__)
#define TSTYLES_TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TSTYLES_TEST_UNDER_ASAN 1
#endif
#endif

namespace tstyles {
namespace {

using Clock = std::chrono::steady_clock;

std::string isolatedError(const IsolatedRead& read, const IsolationLimits& limits = {}) {
    try {
        readIsolated("input.nc", read, limits);
    } catch (const InputError& error) {
        return error.what();
    }
    return "no error";
}

// No reader process outlives its reading: this test process has no child left, not even a zombie.
void expectNoChildLeft() {
    errno = 0;
    EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1);
    EXPECT_EQ(errno, ECHILD);
}

TEST(IsolatedReading, ACrashNamesTheLibraryAndTheStage) {
    const std::string message = isolatedError([](ReadingMonitor& monitor) -> Series {
        monitor.enterStage("damaged.nc", "the NetCDF/HDF5 library", "reading the variable list");
        std::raise(SIGSEGV);
        return {};
    });
    EXPECT_EQ(message, "damaged.nc: the NetCDF/HDF5 library crashed while reading the variable list: the file is "
                       "damaged");
    expectNoChildLeft();
}

TEST(IsolatedReading, ACrashBeforeAnyStageNamesTheFileGiven) {
    const std::string message = isolatedError([](ReadingMonitor&) -> Series { std::abort(); });
    EXPECT_EQ(message, "input.nc: the reader crashed while reading it: the file is damaged");
    expectNoChildLeft();
}

TEST(IsolatedReading, AHangIsEndedWhenItIsSilentPastItsDeadline) {
    IsolationLimits limits;
    limits.silence = std::chrono::milliseconds(1000);
    const auto start = Clock::now();
    const std::string message = isolatedError(
        [](ReadingMonitor& monitor) -> Series {
            monitor.enterStage("stuck.nc", "the NetCDF/HDF5 library", "reading the dimension scales");
            for (;;) pause();
        },
        limits);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    EXPECT_EQ(message, "stuck.nc: the NetCDF/HDF5 library stopped responding while reading the dimension scales (no "
                       "progress in 1 s; the reader was ended): the file is damaged, or reading it is slower than the deadline "
                       "allows");
    EXPECT_GE(seconds, 1.0);
    EXPECT_LT(seconds, 5.0);
    expectNoChildLeft();
}

// The deadline counts silence, not the whole read: a slow reader that keeps reading time-steps
// runs past it many times over.
TEST(IsolatedReading, ProgressKeepsASlowReaderAlive) {
    IsolationLimits limits;
    limits.silence = std::chrono::milliseconds(1000);
    const auto start = Clock::now();
    const Series series = readIsolated(
        "slow.nc",
        [](ReadingMonitor& monitor) {
            Series read;
            for (int step = 0; step < 8; ++step) {
                std::this_thread::sleep_for(std::chrono::milliseconds(400));
                monitor.stepRead(4);
                read.steps.emplace_back().time = step;
            }
            return read;
        },
        limits);
    EXPECT_GE(std::chrono::duration<double>(Clock::now() - start).count(), 3.2);
    ASSERT_EQ(series.size(), 8u);
    EXPECT_EQ(series.steps[7].time, 7.0);
    expectNoChildLeft();
}

TEST(IsolatedReading, AnUnboundedAllocationEndsAtTheMemoryLimit) {
#ifdef TSTYLES_TEST_UNDER_ASAN
    GTEST_SKIP() << "AddressSanitizer's shadow memory rules out a data limit; the reader runs without one";
#endif
    IsolationLimits limits;
    limits.memoryBytes = std::uint64_t(256) << 20;
    const std::string message = isolatedError(
        [](ReadingMonitor& monitor) -> Series {
            monitor.enterStage("huge.nc", "the NetCDF/HDF5 library", "reading the values");
            std::vector<std::vector<char>> held;
            for (;;) held.emplace_back(std::size_t(16) << 20, char(1));
        },
        limits);
    EXPECT_EQ(message, "huge.nc: the NetCDF/HDF5 library ran out of memory while reading the values (a reader may "
                       "take 256.0 MiB): the sizes it declares are too large for this machine, or the file is "
                       "damaged; --max-memory or --steps can ask for less");
    expectNoChildLeft();
}

TEST(IsolatedReading, AnInputErrorComesBackAsItWas) {
    const std::string message =
        isolatedError([](ReadingMonitor&) -> Series { throwInputError("a.nc", "temp", "holds NaN at (1, 2, 3)"); });
    EXPECT_EQ(message, "a.nc: temp: holds NaN at (1, 2, 3)");
    expectNoChildLeft();
}

TEST(IsolatedReading, AFilesystemErrorComesBackWithItsPathAndCode) {
    try {
        readIsolated(
            "x", [](ReadingMonitor&) -> Series {
                throw std::filesystem::filesystem_error("cannot read", "/no/such/file",
                                                        std::make_error_code(std::errc::permission_denied));
            },
            {});
        FAIL() << "no error";
    } catch (const std::filesystem::filesystem_error& error) {
        EXPECT_EQ(error.path1(), "/no/such/file");
        EXPECT_EQ(error.code().value(), EACCES);
    }
}

// Reads `inputs` in-process and isolated: the same series to the bit, or the same error message.
void expectSameEitherWay(const std::vector<std::filesystem::path>& inputs, const ReadOptions& options = {}) {
    SCOPED_TRACE(inputs.front().string());
    std::string inProcessError = "none";
    std::string isolatedErrorText = "none";
    std::optional<Series> inProcess;
    std::optional<Series> isolated;
    try {
        inProcess = openSeries(inputs, options);
    } catch (const InputError& error) {
        inProcessError = error.what();
    }
    try {
        isolated = openSeriesIsolated(inputs, options);
    } catch (const InputError& error) {
        isolatedErrorText = error.what();
    }
    EXPECT_EQ(inProcessError, isolatedErrorText);
    ASSERT_EQ(inProcess.has_value(), isolated.has_value());
    if (inProcess) tstyles_test::expectSameSeries(*inProcess, *isolated);
    if (inProcess) {
        // And the raw values `convert` keeps.
        tstyles_test::expectSameSeries(
            isManifestInput(inputs.front()) ? *inProcess : openRawSeries(inputs, options),
            isManifestInput(inputs.front()) ? *isolated : openRawSeriesIsolated(inputs, options));
    }
}

TEST(IsolatedReading, EveryBundledDatasetIsBitIdentical) {
    int datasets = 0;
    for (const auto& entry : std::filesystem::directory_iterator(bundledDataDirectory()))
        if (std::filesystem::exists(entry.path() / "series.json")) {
            expectSameEitherWay({entry.path() / "series.json"});
            ++datasets;
        }
    EXPECT_GE(datasets, 1);
}

TEST(IsolatedReading, NetcdfAndNiftiFilesAreBitIdentical) {
    const auto folder = tstyles_test::freshFolder("isolated_realistic");
    testdata::writeOceanAnomalies(folder / "ocean.nc");
    testdata::writeMovingBlobNifti(folder / "blob.nii");
    testdata::writeCtPhantom(folder / "ct.nii");
    expectSameEitherWay({folder / "ocean.nc"});
    ReadOptions steps;
    steps.steps = StepSelection{1, std::nullopt, 1};
    steps.resampleTo = glm::ivec3(20, 10, 6);
    expectSameEitherWay({folder / "ocean.nc"}, steps);
    expectSameEitherWay({folder / "blob.nii"});
    expectSameEitherWay({folder / "ct.nii"});
}

// Every file of tests/cli/write_reader_samples (NetCDF classic, 64-bit offset and NetCDF-4, NRRD,
// NIfTI, Isabel, and the ones each reader refuses): read or refused alike.
TEST(IsolatedReading, EveryReaderSampleReadsOrFailsAlike) {
    const auto folder = tstyles_test::freshFolder("isolated_samples");
    const std::string command = std::string(TSTYLES_READER_SAMPLES_WRITER) + " " + folder.string();
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().filename().string().rfind("QCLOUD", 0) == 0) continue;  // Isabel: below, with --dims
        expectSameEitherWay({entry.path()});
        ++files;
    }
    EXPECT_GE(files, 9);
    ReadOptions isabel;
    isabel.rawDims = glm::ivec3(6, 5, 4);
    expectSameEitherWay({folder / "QCLOUDf01.bin", folder / "QCLOUDf02.bin", folder / "QCLOUDf03.bin"}, isabel);
}

}  // namespace
}  // namespace tstyles
