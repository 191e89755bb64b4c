// Writes the warped box (a curvilinear grid with a closed-form mapping, tstyles/data/warped_box.h)
// with a dense blob drifting along its bent i axis: as a tstyles series on a structured grid, or
// with --plot3d as a Plot3D grid and q files. Usage:
//   generate_warped_box --output DIR [--steps N] [--plot3d]
#include <cmath>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "generator_main.h"

#include "tstyles/data/manifest.h"
#include "tstyles/data/warped_box.h"
#include "warped_box/plot3d_writer.h"

namespace {

tstyles::WarpedBox demoBox() {
    tstyles::WarpedBox box;
    box.dims = {33, 33, 17};
    box.spacing = 1.0 / 32.0;
    box.amplitude = {0.15, 0.1, 0.05};
    return box;
}

// Blob density in [0, 1] at node (i, j, k) of time-step `step`: its centre moves along i.
float blobDensity(const tstyles::WarpedBox& box, int step, int steps, glm::ivec3 node) {
    const double travel = steps > 1 ? double(step) / double(steps - 1) : 0.5;
    const glm::dvec3 centre(6.0 + travel * double(box.dims.x - 13), box.dims.y / 2.0, box.dims.z / 2.0);
    const double distance = glm::length(glm::dvec3(node) - centre) / 6.0;
    return float(std::exp(-distance * distance));
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Writes the warped-box structured-grid series (a blob drifting along a bent grid)."};
    std::filesystem::path output;
    int steps = 4;
    bool plot3d = false;
    app.add_option("--output", output, "Directory to write into")->required();
    app.add_option("--steps", steps, "Number of time-steps")->check(CLI::Range(1, 1000));
    app.add_flag("--plot3d", plot3d, "Write grid.xyz and flowNN.q (Plot3D) instead of a tstyles series");
    if (const auto exitCode = generator::parseArguments(app, argc, argv)) return *exitCode;

    const int exitCode = generator::runReportingErrors("generate_warped_box", [&] {
        const tstyles::WarpedBox box = demoBox();
        const tstyles::StructuredGrid grid = box.grid();
        std::filesystem::create_directories(output);
        tstyles::RawSeries series;
        series.name = "warped box";
        series.valueRange = {0.0, 255.0};
        if (plot3d) warped_box::writePlot3DGrid(grid, output / "grid.xyz");
        for (int step = 0; step < steps; ++step) {
            std::vector<float> density;
            for (int k = 0; k < box.dims.z; ++k)
                for (int j = 0; j < box.dims.y; ++j)
                    for (int i = 0; i < box.dims.x; ++i) density.push_back(blobDensity(box, step, steps, {i, j, k}));
            if (plot3d) {
                // Density 1 + blob; momentum along x; energy for a pressure of 1 + 0.4 blob (gamma 1.4).
                std::array<std::vector<float>, 5> q;
                for (float value : density) {
                    q[0].push_back(1.0f + value);
                    q[1].push_back(0.3f * value);
                    q[2].push_back(0.0f);
                    q[3].push_back(0.0f);
                    q[4].push_back(2.5f + value + 0.5f * 0.09f * value * value / (1.0f + value));
                }
                const std::string name = "flow" + std::string(step < 10 ? "0" : "") + std::to_string(step) + ".q";
                warped_box::writePlot3DSolution(box.dims, double(step), q, output / name);
                continue;
            }
            tstyles::RawTimeStep raw;
            raw.time = step;
            raw.structured = grid;
            raw.type = tstyles::ValueType::UInt8;
            for (float value : density) raw.bytes.push_back(std::uint8_t(std::lround(value * 255.0f)));
            series.steps.push_back(std::move(raw));
        }
        if (!plot3d) tstyles::writeSeries(series, output);
    });
    if (exitCode != 0) return exitCode;
    std::cout << "wrote " << steps << " time-steps to " << output.string() << "\n";
    return 0;
}
