// Every reader, with how to recognise its files. Formats whose files hold one volume each become a
// series of several files through eachFileOneStep.
#include "format_table.h"

#include <fstream>

#include "isabel_reader.h"
#include "netcdf_reader.h"
#include "nifti_reader.h"
#include "nrrd_reader.h"
#include "stacked_files.h"

namespace tstyles {
namespace {

bool startsWithNrrdMagic(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[7] = {};
    in.read(magic, 7);
    return in && std::string(magic, 7) == "NRRD000";
}

}  // namespace

const std::vector<SeriesFormat>& seriesFormats() {
    static const std::vector<SeriesFormat> formats = {
        {"NetCDF", {".nc", ".nc4", ".cdf", ".netcdf"}, hasNetcdfSignature,
         stackedFiles([](const std::filesystem::path& file, const ReadOptions& options) {
             return openNetcdf(file, options);
         })},
        {"NIfTI", {".nii", ".nii.gz"}, hasNiftiSignature,
         stackedFiles([](const std::filesystem::path& file, const ReadOptions&) { return openNifti(file); })},
        {"NRRD", {".nrrd", ".nhdr"}, startsWithNrrdMagic,
         stackedFiles([](const std::filesystem::path& file, const ReadOptions&) { return openNrrd(file); })},
        {"Hurricane Isabel raw", {".bin", ".bin.gz"}, isIsabelFileName,
         [](const std::vector<std::filesystem::path>& files, const ReadOptions& options) {
             return openIsabel(files, options.rawDims);
         }},
    };
    return formats;
}

}  // namespace tstyles
