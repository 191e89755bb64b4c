// Every reader, with how to recognise its files. Formats whose files hold one volume each become a
// series of several files through eachFileOneStep.
#include "format_table.h"

#include "dicom/dicom_files.h"
#include "dicom/dicom_reader.h"
#include "file_magic.h"
#include "isabel/isabel_reader.h"
#include "netcdf/netcdf_reader.h"
#include "nifti/nifti_reader.h"
#include "nrrd/nrrd_reader.h"
#include "zarr/ome_zarr_reader.h"
#include "plot3d/plot3d_source.h"
#include "stacked_files.h"
#include "vtk/vtk_reader.h"
#include "tiff/tiff_reader.h"
#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

bool startsWithNrrdMagic(const std::filesystem::path& file) { return hasMagicAt(fileStart(file, 7), 0, "NRRD000"); }

// How the desktop's MIME database recognises our types' content (shared-mime-info <match> elements).
// NIfTI-1 single file: "n+1" at byte 344; NIfTI-2: "n+2" at byte 4.
constexpr const char* kNiftiMagic =
    R"(<match type="string" offset="344" value="n+1"/><match type="string" offset="4" value="n+2"/>)";
constexpr const char* kNrrdMagic = R"(<match type="string" offset="0" value="NRRD000"/>)";
// The root element of a VTK XML file, after the XML declaration; a legacy VTK file's first line.
constexpr const char* kVtkXmlMagic = R"(<match type="string" offset="0:256" value="&lt;VTKFile"/>)";
constexpr const char* kVtkLegacyMagic = R"(<match type="string" offset="0" value="# vtk DataFile Version"/>)";

}  // namespace

const std::vector<SeriesFormat>& seriesFormats() {
    static const std::vector<SeriesFormat> formats = {
        {"NetCDF", {".nc", ".nc4", ".cdf", ".netcdf"}, {{"application/x-netcdf"}}, ".nc .nc4 .cdf .netcdf",
         {"--var", "--time-dim", "--index-axes"}, hasNetcdfSignature,
         stackedFiles([](const std::filesystem::path& file, const ReadOptions& options) {
             return openNetcdf(file, options);
         })},
        {"NIfTI", {".nii", ".nii.gz"}, {{"application/x-nifti", "NIfTI volume", kNiftiMagic}}, ".nii .nii.gz", {}, hasNiftiSignature,
         stackedFiles([](const std::filesystem::path& file, const ReadOptions&) { return openNifti(file); })},
        {"NRRD", {".nrrd", ".nhdr"}, {{"application/x-nrrd", "NRRD volume", kNrrdMagic}}, ".nrrd .nhdr", {}, startsWithNrrdMagic,
         stackedFiles([](const std::filesystem::path& file, const ReadOptions&) { return openNrrd(file); })},
        // ParaView's time series: a collection (.pvd, .series) or the data sets themselves, XML
        // (serial or parallel) or legacy.
        {"VTK", {".pvd", ".series", ".vti", ".vtr", ".vts", ".pvti", ".pvtr", ".pvts", ".vtk"},
         {{"application/x-vtk-xml", "VTK XML data set or ParaView collection", kVtkXmlMagic},
          {"application/x-vtk", "VTK legacy data set", kVtkLegacyMagic}},
         ".pvd .series .vti .vtr .vts .pvti .pvtr .pvts .vtk", {"--var"}, hasVtkSignature, openVtkSeries},
        // Files, lists of files, or folders (nested ones too) of one or more series; --series picks one.
        {"DICOM", {".dcm", ".dicom"}, {{"application/dicom"}}, ".dcm .dicom, files with the DICM magic, their folder, or a DICOMDIR", {"--series"},
         hasDicomMagic, openDicom, isDicomFolder},
        // By name only: ".bin" alone says too little (and no MIME type: the desktop goes by names too).
        {"Hurricane Isabel raw", {}, {}, "VARIABLEfHH.bin or .bin.gz", {"--dims"}, isIsabelFileName,
         [](const std::vector<std::filesystem::path>& files, const ReadOptions& options) {
             return openIsabel(files, options.rawDims);
         }},
        // A store is a folder; its zarr.json or .zattrs names it too. The desktop has no type for a
        // folder of one kind.
        {"OME-Zarr", {"zarr.json", ".zattrs"}, {}, "a .zarr store folder, or its zarr.json or .zattrs", {"--channel", "--level"},
         {},
         [](const std::vector<std::filesystem::path>& files, const ReadOptions& options) {
             if (files.size() > 1)
                 throwInputError(files[1], "", "an OME-Zarr store holds its whole series: give the store alone");
             return openOmeZarr(files.front(), options);
         },
         isOmeZarrFolder},
        // Microscopy: one file, a list of files or a folder of them, read as pages (tiff_reader.h).
        {"TIFF", {".tif", ".tiff"}, {{"image/tiff"}}, ".tif .tiff (ImageJ, OME-TIFF, plain pages), or a folder of them",
         {"--channel", "--dims", "--axes", "--level"}, hasTiffSignature, openTiff, isTiffFolder},
        // Last: its content sniff reads the whole file to find a layout that fits. No MIME type: its
        // names (.xyz, .x, .g) are other formats' too, and its files have no magic.
        {kPlot3DFormatName, {".xyz", ".x", ".g", ".grd"}, {}, ".xyz .x .g .grd, with --solution",
         {"--var", "--solution", "--block", "--gamma"}, looksLikePlot3DGrid,
         [](const std::vector<std::filesystem::path>& files, const ReadOptions& options) {
             if (files.size() > 1)
                 throwInputError(files[1], "", "a Plot3D series is one grid file; give its solution files with --solution");
             Plot3DOptions plot3d;
             plot3d.gridFile = files.front();
             plot3d.solutionFiles = options.solutionFiles;
             if (!options.variable.empty()) plot3d.variable = options.variable;
             plot3d.block = options.block;
             plot3d.gamma = options.gamma;
             return openPlot3DSource(plot3d);
         }},
    };
    return formats;
}

}  // namespace tstyles
