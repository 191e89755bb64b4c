// The Plot3D reader on files the test writes itself: every combination of byte order, record
// markers, block header and precision, IBLANK, derived quantities, and bad input.
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "series_equality.h"
#include "test_dataset.h"
#include "tstyles/data/isolated_reading.h"
#include "tstyles/data/series_opener.h"
#include "tstyles/data/plot3d.h"
#include "tstyles/data/warped_box.h"

namespace tstyles {
namespace {

struct Flavour {
    bool bigEndian = false;
    bool records = false;
    bool multiBlock = false;
    int precision = 4;
    bool iblank = false;
};

std::string flavourName(const Flavour& f) {
    return std::string(f.bigEndian ? "big" : "little") + (f.records ? "_records" : "_raw") +
           (f.multiBlock ? "_multi" : "_single") + "_f" + std::to_string(f.precision * 8) + (f.iblank ? "_iblank" : "");
}

// Writes Plot3D records the way a Fortran or C program would.
class Plot3DWriter {
public:
    explicit Plot3DWriter(Flavour flavour) : flavour_(flavour) {}

    void beginRecord() { recordStart_ = bytes_.size(); if (flavour_.records) integer(0); }
    void endRecord() {
        if (!flavour_.records) return;
        const auto payload = std::uint32_t(bytes_.size() - recordStart_ - 4);
        for (int index = 0; index < 4; ++index) bytes_[recordStart_ + std::size_t(index)] = byteOf(payload, index, 4);
        integer(std::int32_t(payload));
    }
    void integer(std::int32_t value) { append(std::bit_cast<std::uint32_t>(value), 4); }
    void real(double value) {
        if (flavour_.precision == 8) append(std::bit_cast<std::uint64_t>(value), 8);
        else append(std::bit_cast<std::uint32_t>(float(value)), 4);
    }
    void header(const std::vector<glm::ivec3>& blocks) {
        if (flavour_.multiBlock) {
            beginRecord();
            integer(std::int32_t(blocks.size()));
            endRecord();
        }
        beginRecord();
        for (const glm::ivec3& dims : blocks) {
            integer(dims.x);
            integer(dims.y);
            integer(dims.z);
        }
        endRecord();
    }
    const std::vector<std::uint8_t>& bytes() const { return bytes_; }

private:
    std::uint8_t byteOf(std::uint64_t value, int index, int size) const {
        const int shift = flavour_.bigEndian ? (size - 1 - index) * 8 : index * 8;
        return std::uint8_t(value >> shift);
    }
    void append(std::uint64_t value, int size) {
        for (int index = 0; index < size; ++index) bytes_.push_back(byteOf(value, index, size));
    }

    Flavour flavour_;
    std::vector<std::uint8_t> bytes_;
    std::size_t recordStart_ = 0;
};

// The q values at node n of a time-step: density 1 + n/1000 + t, momentum (n, 2n, 3n)/100, energy 10.
std::array<double, 5> qAt(std::size_t node, double time) {
    const double n = double(node);
    return {1.0 + n / 1000.0 + time, n / 100.0, 2.0 * n / 100.0, 3.0 * n / 100.0, 10.0};
}

// Block 0 is a small 3x2x2 box; the last block is the warped box (so block 1 in multi-block files).
std::vector<StructuredGrid> testBlocks(bool multiBlock) {
    std::vector<StructuredGrid> blocks;
    if (multiBlock) {
        std::vector<glm::vec3> nodes;
        for (int k = 0; k < 2; ++k)
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 3; ++i) nodes.emplace_back(i, j, k);
        blocks.push_back(makeStructuredGrid({3, 2, 2}, nodes));
    }
    WarpedBox box;
    box.dims = {9, 7, 5};
    box.spacing = 0.125;
    blocks.push_back(box.grid());
    return blocks;
}

std::vector<glm::ivec3> dimsOf(const std::vector<StructuredGrid>& blocks) {
    std::vector<glm::ivec3> dims;
    for (const StructuredGrid& grid : blocks) dims.push_back(grid.dims);
    return dims;
}

std::vector<std::uint8_t> gridBytes(const Flavour& flavour, const std::vector<StructuredGrid>& blocks) {
    Plot3DWriter writer(flavour);
    writer.header(dimsOf(blocks));
    for (const StructuredGrid& grid : blocks) {
        writer.beginRecord();
        for (int axis = 0; axis < 3; ++axis)
            for (const glm::vec3& node : *grid.nodes) writer.real(node[axis]);
        if (flavour.iblank)
            for (std::size_t node = 0; node < grid.voxelCount(); ++node) writer.integer(node == 5 ? 0 : 1);
        writer.endRecord();
    }
    return writer.bytes();
}

std::vector<std::uint8_t> solutionBytes(const Flavour& flavour, const std::vector<StructuredGrid>& blocks, double time) {
    Plot3DWriter writer(flavour);
    writer.header(dimsOf(blocks));
    for (const StructuredGrid& grid : blocks) {
        writer.beginRecord();
        for (double value : {0.5, 0.0, 1e6, time}) writer.real(value);  // mach, alpha, Reynolds, time
        writer.endRecord();
        writer.beginRecord();
        for (std::size_t component = 0; component < 5; ++component)
            for (std::size_t node = 0; node < grid.voxelCount(); ++node) writer.real(qAt(node, time)[component]);
        writer.endRecord();
    }
    return writer.bytes();
}

Plot3DOptions writeDataset(const std::string& name, const Flavour& flavour, std::vector<double> times = {0.0, 0.5}) {
    const auto folder = tstyles_test::freshFolder("plot3d_" + name);
    const std::vector<StructuredGrid> blocks = testBlocks(flavour.multiBlock);
    Plot3DOptions options;
    options.gridFile = folder / "grid.xyz";
    tstyles_test::writeBytes(options.gridFile, gridBytes(flavour, blocks));
    for (std::size_t index = 0; index < times.size(); ++index) {
        options.solutionFiles.push_back(folder / ("flow" + std::to_string(index) + ".q"));
        tstyles_test::writeBytes(options.solutionFiles.back(), solutionBytes(flavour, blocks, times[index]));
    }
    options.block = flavour.multiBlock ? 1 : 0;
    return options;
}

std::string readError(const Plot3DOptions& options) {
    try {
        readPlot3D(options);
    } catch (const InputError& error) {
        return error.what();
    }
    return "no error";
}

TEST(Plot3D, ReadsEveryLayout) {
    const StructuredGrid expected = testBlocks(false).back();
    for (bool bigEndian : {false, true})
        for (bool records : {false, true})
            for (bool multiBlock : {false, true})
                for (int precision : {4, 8})
                    for (bool iblank : {false, true}) {
                        const Flavour flavour{bigEndian, records, multiBlock, precision, iblank};
                        SCOPED_TRACE(flavourName(flavour));
                        const Series series = readPlot3D(writeDataset(flavourName(flavour), flavour));
                        ASSERT_EQ(series.size(), 2u);
                        EXPECT_EQ(series.steps[0].time, 0.0);
                        EXPECT_EQ(series.steps[1].time, 0.5);
                        const StructuredGrid* grid = series.steps[1].structured();
                        ASSERT_NE(grid, nullptr);
                        EXPECT_EQ(grid->nodes, series.steps[0].structured()->nodes);
                        EXPECT_EQ(grid->dims, expected.dims);
                        for (std::size_t node = 0; node < expected.voxelCount(); ++node)
                            ASSERT_EQ((*grid->nodes)[node], (*expected.nodes)[node]) << "node " << node;
                        // Density 1 + n/1000 + t over [1, 1.5 + 314/1000]: node 100 of step 1.
                        const double low = 1.0, high = 1.5 + double(expected.voxelCount() - 1) / 1000.0;
                        EXPECT_EQ(series.valueRange[0], low);
                        EXPECT_NEAR(series.valueRange[1], high, 1e-6);
                        EXPECT_NEAR(series.steps[1].density[100], (1.6 - low) / (high - low), 1e-6);
                        EXPECT_EQ(isMissing(series.steps[0].density[5]), iblank);
                    }
}

TEST(Plot3D, DerivedQuantities) {
    Plot3DOptions options = writeDataset("derived", Flavour{}, {0.0});
    const std::size_t node = 40;
    const auto q = qAt(node, 0.0);
    const double momentum2 = q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    const auto valueOf = [&](const std::string& variable) {
        options.variable = variable;
        const Series series = readPlot3D(options);
        return series.valueRange[0] + series.steps[0].density[node] * (series.valueRange[1] - series.valueRange[0]);
    };
    EXPECT_NEAR(valueOf("density"), q[0], 1e-5);
    EXPECT_NEAR(valueOf("y-momentum"), q[2], 1e-5);
    EXPECT_NEAR(valueOf("momentum-magnitude"), std::sqrt(momentum2), 1e-5);
    EXPECT_NEAR(valueOf("pressure"), 0.4 * (q[4] - 0.5 * momentum2 / q[0]), 1e-4);
}

TEST(Plot3D, TruncatedGridIsReported) {
    const Plot3DOptions options = writeDataset("truncated", Flavour{});
    std::filesystem::resize_file(options.gridFile, 300);
    const std::string message = readError(options);
    EXPECT_NE(message.find("grid.xyz: Plot3D grid file is truncated: its header announces 1 block(s) of 9x7x5 nodes, "
                           "which need at least 3792 bytes, found 300"),
              std::string::npos)
        << message;
}

TEST(Plot3D, SolutionDimsMustMatchTheGrid) {
    Plot3DOptions options = writeDataset("mismatch", Flavour{});
    WarpedBox other;
    other.dims = {9, 7, 4};
    tstyles_test::writeBytes(options.solutionFiles[1], solutionBytes(Flavour{}, {other.grid()}, 1.0));
    const std::string message = readError(options);
    EXPECT_NE(message.find("flow1.q: block 0 has 9x7x4 nodes but the grid"), std::string::npos) << message;
    EXPECT_NE(message.find("has 9x7x5 in that block"), std::string::npos) << message;
}

// NaN in any of a node's five values leaves the node without data, as IBLANK 0 does; an infinity
// is an error naming the node.
TEST(Plot3D, NaNIsMissingAndInfinitiesAreReported) {
    Plot3DOptions options = writeDataset("nan", Flavour{}, {0.0});
    std::vector<std::uint8_t> bytes = solutionBytes(Flavour{}, testBlocks(false), 0.0);
    // The third array (y-momentum) of node 7: after 3 dims, 4 reals and 2 * 315 + 7 reals.
    const std::size_t offset = 12 + 16 + (2 * 315 + 7) * 4;
    const auto writeAtNode7 = [&](float value) {
        const auto bits = std::bit_cast<std::uint32_t>(value);
        for (int index = 0; index < 4; ++index) bytes[offset + std::size_t(index)] = std::uint8_t(bits >> (8 * index));
        tstyles_test::writeBytes(options.solutionFiles[0], bytes);
    };
    writeAtNode7(std::numeric_limits<float>::quiet_NaN());
    const Series series = readPlot3D(options);
    EXPECT_TRUE(isMissing(series.steps[0].density[7]));
    EXPECT_FALSE(isMissing(series.steps[0].density[6]));
    EXPECT_FALSE(isMissing(series.steps[0].density[8]));

    writeAtNode7(std::numeric_limits<float>::infinity());
    const std::string message = readError(options);
    EXPECT_NE(message.find("flow0.q: infinite y-momentum at node (7, 0, 0) of block 0"), std::string::npos)
        << message;
}

TEST(Plot3D, BadOptionsAndUnknownFilesAreReported) {
    Plot3DOptions options = writeDataset("options", Flavour{});
    options.variable = "vorticity";
    EXPECT_NE(readError(options).find("--var: unknown Plot3D variable 'vorticity' (known: density, x-momentum"),
              std::string::npos);
    options.variable = "density";
    options.block = 3;
    EXPECT_NE(readError(options).find("has 1 block(s); block 3 was asked for"), std::string::npos);
    options.block = 0;
    tstyles_test::writeText(options.solutionFiles[0], "this is not Plot3D at all, just some text\n");
    EXPECT_NE(readError(options).find("flow0.q: not a binary 3D Plot3D solution file"), std::string::npos)
        << readError(options);
    options.solutionFiles.clear();
    EXPECT_NE(readError(options).find("needs at least one solution (q) file"), std::string::npos);
}

// A function file: dims and a variable count per block, then the variables (function K at node n:
// K * 100 + n / 10).
std::vector<std::uint8_t> functionBytes(const Flavour& flavour, const std::vector<StructuredGrid>& blocks,
                                        int functions) {
    Plot3DWriter writer(flavour);
    if (flavour.multiBlock) {
        writer.beginRecord();
        writer.integer(std::int32_t(blocks.size()));
        writer.endRecord();
    }
    writer.beginRecord();
    for (const StructuredGrid& grid : blocks) {
        for (int axis = 0; axis < 3; ++axis) writer.integer(grid.dims[axis]);
        writer.integer(functions);
    }
    writer.endRecord();
    for (const StructuredGrid& grid : blocks) {
        writer.beginRecord();
        for (int function = 0; function < functions; ++function)
            for (std::size_t node = 0; node < grid.voxelCount(); ++node) writer.real(function * 100.0 + node / 10.0);
        writer.endRecord();
    }
    return writer.bytes();
}

TEST(Plot3D, FunctionFilesGiveTheirVariablesByIndex) {
    for (const Flavour flavour : {Flavour{}, Flavour{true, true, true, 8, false}}) {
        SCOPED_TRACE(flavourName(flavour));
        Plot3DOptions options = writeDataset("function_" + flavourName(flavour), flavour, {0.0});
        const std::vector<StructuredGrid> blocks = testBlocks(flavour.multiBlock);
        options.solutionFiles = {options.gridFile.parent_path() / "a.f", options.gridFile.parent_path() / "b.f"};
        for (const auto& file : options.solutionFiles) tstyles_test::writeBytes(file, functionBytes(flavour, blocks, 3));
        options.variable = "function-2";
        const Series series = readPlot3D(options);
        ASSERT_EQ(series.size(), 2u);
        EXPECT_EQ(series.steps[1].time, 1.0);  // function files store no time
        EXPECT_NEAR(series.valueRange[0], 200.0, 1e-9);
        EXPECT_NEAR(series.valueRange[1], 200.0 + (blocks.back().voxelCount() - 1) / 10.0, 1e-4);
        const double value =
            series.valueRange[0] + series.steps[0].density[40] * (series.valueRange[1] - series.valueRange[0]);
        EXPECT_NEAR(value, 204.0, 1e-3);

        options.variable = "function-3";
        EXPECT_NE(readError(options).find("a.f: --var: block " + std::to_string(options.block) +
                                          " has 3 function(s); function-3 was asked for"),
                  std::string::npos)
            << readError(options);
        options.variable = "pressure";
        EXPECT_NE(readError(options).find("'pressure' is a solution (q) variable"), std::string::npos)
            << readError(options);
    }
}

TEST(Plot3D, TruncatedFunctionFileIsReported) {
    Plot3DOptions options = writeDataset("function_truncated", Flavour{}, {0.0});
    options.solutionFiles = {options.gridFile.parent_path() / "a.f"};
    std::vector<std::uint8_t> bytes = functionBytes(Flavour{}, testBlocks(false), 2);
    bytes.erase(bytes.end() - 8, bytes.end());
    tstyles_test::writeBytes(options.solutionFiles[0], bytes);
    options.variable = "function-0";
    EXPECT_NE(readError(options).find("a.f: Plot3D function file is truncated: its header announces 1 block(s) of "
                                      "9x7x5 nodes"),
              std::string::npos)
        << readError(options);
}

TEST(Plot3D, GridExtensions) {
    EXPECT_TRUE(hasPlot3DGridExtension("a/b/wing.xyz"));
    EXPECT_TRUE(hasPlot3DGridExtension("WING.X"));
    EXPECT_TRUE(hasPlot3DGridExtension("wing.g"));
    EXPECT_FALSE(hasPlot3DGridExtension("series.json"));
}

// Through the reader process the structured grid, its shared nodes and the values come back to the bit.
TEST(Plot3D, IsolatedReadingIsBitIdentical) {
    const Flavour flavour{true, true, true, 8, true};
    const Plot3DOptions written = writeDataset("isolated", flavour, {0.0, 0.5, 1.5});
    ReadOptions options;
    options.solutionFiles = written.solutionFiles;
    options.block = written.block;
    options.variable = "pressure";
    const Series inProcess = openSeries(written.gridFile, options);
    const Series isolated = openSeriesIsolated({written.gridFile}, options);
    tstyles_test::expectSameSeries(inProcess, isolated);
    EXPECT_EQ(isolated.steps[0].structured()->nodes, isolated.steps[2].structured()->nodes);
}

}  // namespace
}  // namespace tstyles
