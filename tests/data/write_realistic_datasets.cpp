// Writes the realistic sample files (realistic_datasets.h) into a folder, for trying the automatic
// scene on files shaped like scientists' own and for the README's gallery:
//   write_realistic_datasets FOLDER
#include <filesystem>
#include <iostream>

#include "realistic_datasets.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: write_realistic_datasets FOLDER\n";
        return 2;
    }
    try {
        const std::filesystem::path folder = argv[1];
        std::filesystem::create_directories(folder);
        using namespace tstyles::testdata;
        writeOceanAnomalies(folder / "ocean-anomalies.nc");
        writeOceanEddy(folder / "ocean-eddy.nc");
        writeMovingBlobNifti(folder / "moving-blob.nii");
        writeCtPhantom(folder / "ct-phantom.nii");
        writeOceanClimatology(folder / "woa-climatology.nc");
        writeRegionalForecast(folder / "forecast.nc");
        writeFmriRun(folder / "fmri-run.nii");
        writeBrainFollowUp(folder / "brain-follow-up.nii");
        writeCtHeadPerfusion(folder / "ct-head-perfusion.nii");
        writeMrSlab(folder / "mr-slab.nii");
    } catch (const std::exception& error) {
        std::cerr << "write_realistic_datasets: " << error.what() << "\n";
        return 2;
    }
    return 0;
}
