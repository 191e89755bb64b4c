// Reading Plot3D (NASA's structured-grid CFD format): a grid file (x, y, z per node, optionally
// IBLANK) and one solution ("q") file per time-step (density, momentum x/y/z, energy per node) or
// one function file (".f", ".fun": any number of variables per node) per time-step.
// Binary only, 3D, single or multi-block, big- or little-endian, float32 or float64, with or
// without Fortran record markers: the layout is found from the file size and header.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "tstyles/data/series.h"

namespace tstyles {

struct Plot3DOptions {
    std::filesystem::path gridFile;
    // One solution (.q) or function (.f, .fun) file per time-step, in time order.
    std::vector<std::filesystem::path> solutionFiles;
    // Which quantity becomes the density: plot3DVariableNames() for q files, "function-K" (K from 0)
    // for function files.
    std::string variable = "density";
    // Which block of a multi-block file (a series holds one grid per time-step).
    int block = 0;
    // Ratio of specific heats, for pressure = (gamma - 1) (energy - |momentum|^2 / (2 density)).
    double gamma = 1.4;
};

// density, x-momentum, y-momentum, z-momentum, energy, momentum-magnitude, pressure.
std::vector<std::string> plot3DVariableNames();

// Whether a path names a Plot3D grid file by its extension (.xyz, .x, .g, .grd; any case).
bool hasPlot3DGridExtension(const std::filesystem::path& path);

// One time-step per solution file, all on the chosen block's grid (one shared StructuredGrid).
// Times are the solution files' own time values when they increase, else 0, 1, 2, ... Nodes with
// IBLANK 0, or NaN in any of their solution (or the function's) values, are missing data. Every
// problem is an InputError naming the file and what is wrong.
Series readPlot3D(const Plot3DOptions& options);

}  // namespace tstyles
