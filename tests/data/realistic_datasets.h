// Files in the shapes scientists' files have, written for the automatic-scene tests and the
// README's gallery (tests/data/write_realistic_datasets.cpp): a CF NetCDF ocean, a 4D NIfTI with a
// moving region on a zero background, a CT-like int16 volume with air at -1000.
#pragma once

#include <filesystem>

namespace tstyles::testdata {

// CF-1.8 NetCDF-4, thetao(time 3, depth 12, lat 30, lon 40), degrees Celsius: longitude -40..-20
// degrees_east, latitude 30..45 degrees_north, depth 0..1000 m (uneven, positive down), time "days
// since 1950-01-01" on the noleap calendar (1969-01-19, 1969-02-19, 1969-03-19). Land (_FillValue
// 1e20) in the south-east corner at every depth. An ocean at 4 degC with three warm anomalies, one
// per time-step: time-step 0 at the surface in the north-west, 1 mid-basin at 300 m, 2 near the
// bottom in the south-west.
void writeOceanAnomalies(const std::filesystem::path& file);

// A larger ocean for the gallery: thetao(time 6, depth 20, lat 60, lon 80), a thermocline and a
// warm eddy drifting east, a surface warming month by month, land in the north-west; monthly on the
// noleap calendar.
void writeOceanEddy(const std::filesystem::path& file);

// NIfTI-1 (.nii), 56 x 40 x 36 voxels of 3 mm, RAS sform, 4 volumes with TR 2 s (xyzt_units mm and
// s): zero everywhere but a sphere of value 100, radius 4 voxels, that moves 12 voxels along +x (the
// patient's right in RAS) each volume: time-step i is centred on voxel (10 + 12 i, 20, 18).
void writeMovingBlobNifti(const std::filesystem::path& file);

// NIfTI-1 int16 CT: 96 x 96 x 64 voxels of 0.8 x 0.8 x 1.5 mm, RAS; air at -1000 HU outside a body
// (an elliptic cylinder of soft tissue at 40 HU under a layer of fat at -100 HU) with a spine of bone
// (700 HU); 3 time-steps in
// which a lesion (120 HU) grows in the body. xyzt_units mm and s, TR 60 s.
void writeCtPhantom(const std::filesystem::path& file);

}  // namespace tstyles::testdata
