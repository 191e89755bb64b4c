// Loading the dataset a command names: a tstyles manifest (or its folder), or a Plot3D grid file
// (by its extension .xyz/.x/.g/.grd, when solution files are given, or when the file does not
// start like JSON) with the Plot3D options.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "tstyles/data/plot3d.h"
#include "tstyles/data/series.h"

namespace tstyles::cli {

struct Plot3DCliOptions {
    std::vector<std::filesystem::path> solutions;
    std::string variable = "density";
    int block = 0;
    double gamma = 1.4;
};

// --solution FILE[,FILE...], --var NAME, --block N, --gamma G.
void addPlot3DOptions(CLI::App& command, Plot3DCliOptions& options);

Series loadDataset(const std::filesystem::path& dataset, const Plot3DCliOptions& plot3d);

}  // namespace tstyles::cli
