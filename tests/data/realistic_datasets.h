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

// The five shapes of issue 40's first pictures, each as the files scientists have them:
// A global monthly ocean climatology as the World Ocean Atlas writes it: t_an(time 12, depth 19,
// lat 45, lon 90), degrees_celsius, 4-degree cells, the 19 standard levels 0 .. 1000 m (uneven),
// time "months since 0000-01-01 00:00:00" at mid-month (0.5 .. 11.5) with a `climatology`
// attribute and its bounds; continents (and shelves widening with depth) as _FillValue. The surface
// follows the seasons (the north warmest in August, the south in February); the layers below lag
// (a month per 40 m) and shrink (e-folding over 80 m); the deep water does not change.
void writeOceanClimatology(const std::filesystem::path& file);

// A regional forecast as ECMWF's grids come: clwc(time 7, level 10, latitude 81, longitude 121),
// kg kg**-1, 0.25 degrees over 30..50 N, -110..-80 E, pressure levels 1000 .. 300 hPa, time "hours
// since 2026-11-28 00:00:00" every 6 hours (+0 h .. +36 h). A cold front's cloud band sweeps east
// and deepens; a cloud over the mountains in the west stays the same at every step.
void writeRegionalForecast(const std::filesystem::path& file);

// A low-resolution fMRI run: NIfTI-1 int16, 64 x 64 x 30 voxels of 3.5 x 3.5 x 4 mm, 40 volumes,
// TR 2 s. A brain (about 600) in a dim background, temporal noise of standard deviation 6 (a
// temporal SNR of 100), and a block design (10 volumes on, 10 off) that raises two small regions
// (visual cortex at the back, motor cortex at the top) by 3 %.
void writeFmriRun(const std::filesystem::path& file);

// A brain scanned twice (baseline and follow-up): NIfTI-1 int16, 80 x 96 x 72 voxels of 2 mm, 2
// volumes. Grey and white matter, dark ventricles, independent noise of 2 % in each scan, and a
// bright lesion whose radius grows from 5 to 7 voxels.
void writeBrainFollowUp(const std::filesystem::path& file);

// A CT perfusion of the head: NIfTI-1 int16 HU, 96 x 96 x 48 voxels of 2 x 2 x 3 mm, 4 time-steps
// 4 s apart. Air at -1000 HU, a skull at 1200 HU, brain at 35 HU with ventricles at 8 HU, noise of
// 6 HU in each time-step; contrast fills three arteries (40 to 320 HU, peaking at the third
// time-step) and the right hemisphere's tissue enhances by 15 HU.
void writeCtHeadPerfusion(const std::filesystem::path& file);

// A contrast-enhanced MR slab: NIfTI-1 int16, 128 x 128 x 24 voxels of 2 x 2 x 2.2 mm (a 256 mm
// field, 53 mm thick, axial), 3 time-steps a minute apart. Scalp, skull, grey and white matter,
// two dark lateral ventricles, noise of 2 %, and a lesion in the right frontal lobe that enhances
// from 700 to 1120 and 1300.
void writeMrSlab(const std::filesystem::path& file);

}  // namespace tstyles::testdata
