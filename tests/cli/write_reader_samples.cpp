// Writes small files in the formats `tstyles` reads, good and bad, for tests/cli/readers_test.sh:
//   write_reader_samples FOLDER
// Each file's content is stated next to the code that writes it, so the test can state what
// `tstyles` must report. NetCDF through libnetcdf, NIfTI through libnifti2, NRRD and the Isabel
// raw files byte by byte.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <netcdf.h>
#include <nifti2_io.h>
#include <zlib.h>

namespace {

void check(int status, const std::string& what) {
    if (status != NC_NOERR) throw std::runtime_error(what + ": " + nc_strerror(status));
}

void writeBytes(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

// ocean.nc (netCDF-4): temp(time 3, depth 3, lat 4, lon 5) float, value = 100 t + index in the
// volume (0..59), _FillValue -999 at (lon 0, lat 0, depth 0) of every time-step; depth levels
// 0, 10, 50 (uneven); time in hours 0, 6, 12. A second variable salt(time, depth, lat, lon) makes
// --var necessary.
void writeOcean(const std::filesystem::path& file) {
    int nc = 0, dims[4] = {}, temp = 0, salt = 0, time = 0, depth = 0;
    check(nc_create(file.c_str(), NC_NETCDF4 | NC_CLOBBER, &nc), file.string());
    check(nc_def_dim(nc, "time", 3, &dims[0]), "time");
    check(nc_def_dim(nc, "depth", 3, &dims[1]), "depth");
    check(nc_def_dim(nc, "lat", 4, &dims[2]), "lat");
    check(nc_def_dim(nc, "lon", 5, &dims[3]), "lon");
    check(nc_def_var(nc, "time", NC_DOUBLE, 1, &dims[0], &time), "time var");
    check(nc_put_att_text(nc, time, "units", 24, "hours since 2000-01-01 0"), "units");
    check(nc_def_var(nc, "depth", NC_DOUBLE, 1, &dims[1], &depth), "depth var");
    check(nc_def_var(nc, "temp", NC_FLOAT, 4, dims, &temp), "temp");
    check(nc_def_var(nc, "salt", NC_FLOAT, 4, dims, &salt), "salt");
    const float fill = -999.0f;
    check(nc_put_att_float(nc, temp, "_FillValue", NC_FLOAT, 1, &fill), "fill");
    check(nc_enddef(nc), "enddef");
    const double times[3] = {0, 6, 12}, depths[3] = {0, 10, 50};
    check(nc_put_var_double(nc, time, times), "times");
    check(nc_put_var_double(nc, depth, depths), "depths");
    std::vector<float> values(180), salts(180, 35.0f);
    for (std::size_t index = 0; index < values.size(); ++index)
        values[index] = index % 60 == 0 ? fill : float(100 * (index / 60) + index % 60);
    for (std::size_t index = 0; index < salts.size(); ++index) salts[index] += float(index % 7);
    check(nc_put_var_float(nc, temp, values.data()), "temp values");
    check(nc_put_var_float(nc, salt, salts.data()), "salt values");
    check(nc_close(nc), "close");
}

// A NetCDF file with one 4D float variable over dimensions a, b, c, d: no time dimension to find.
// With a = 2 the first dimension can be named as the time dimension (--time-dim a).
void writeNoTime(const std::filesystem::path& file) {
    int nc = 0, dims[4] = {}, variable = 0;
    check(nc_create(file.c_str(), NC_CLOBBER, &nc), file.string());
    const char* names[4] = {"a", "b", "c", "d"};
    const std::size_t lengths[4] = {2, 2, 3, 4};
    for (int axis = 0; axis < 4; ++axis) check(nc_def_dim(nc, names[axis], lengths[axis], &dims[axis]), names[axis]);
    check(nc_def_var(nc, "v", NC_FLOAT, 4, dims, &variable), "v");
    check(nc_enddef(nc), "enddef");
    std::vector<float> values(48);
    for (std::size_t index = 0; index < values.size(); ++index) values[index] = float(index);
    check(nc_put_var_float(nc, variable, values.data()), "values");
    check(nc_close(nc), "close");
}

// temp(time 2, z 2, y 2, x 3) float holding its index, but `odd` at index 7, which no attribute
// declares missing: NaN there is missing data, Inf is an error.
void writeWithOddValue(const std::filesystem::path& file, float odd) {
    int nc = 0, dims[4] = {}, variable = 0;
    check(nc_create(file.c_str(), NC_CLOBBER, &nc), file.string());
    const char* names[4] = {"time", "z", "y", "x"};
    const std::size_t lengths[4] = {2, 2, 2, 3};
    for (int axis = 0; axis < 4; ++axis) check(nc_def_dim(nc, names[axis], lengths[axis], &dims[axis]), names[axis]);
    check(nc_def_var(nc, "temp", NC_FLOAT, 4, dims, &variable), "temp");
    check(nc_enddef(nc), "enddef");
    std::vector<float> values(24);
    for (std::size_t index = 0; index < values.size(); ++index) values[index] = float(index);
    values[7] = odd;
    check(nc_put_var_float(nc, variable, values.data()), "values");
    check(nc_close(nc), "close");
}

// count(time 2, z 2, y 2, x 2) as 64-bit integers (netCDF-4): a type the readers do not take.
void writeInt64(const std::filesystem::path& file) {
    int nc = 0, dims[4] = {}, variable = 0;
    check(nc_create(file.c_str(), NC_NETCDF4 | NC_CLOBBER, &nc), file.string());
    const char* names[4] = {"time", "z", "y", "x"};
    for (int axis = 0; axis < 4; ++axis) check(nc_def_dim(nc, names[axis], 2, &dims[axis]), names[axis]);
    check(nc_def_var(nc, "count", NC_INT64, 4, dims, &variable), "count");
    check(nc_enddef(nc), "enddef");
    std::vector<long long> values(16, 3);
    check(nc_put_var_longlong(nc, variable, values.data()), "values");
    check(nc_close(nc), "close");
}

// volume.nrrd: 4 x 3 x 2 voxels, 3 time-steps, uchar value = 2 * voxel + step (0..48), spacing 0.5, 1, 2,
// origin (1, 2, 3), time the fourth (slowest) axis.
void writeNrrd(const std::filesystem::path& file) {
    std::string data;
    for (int index = 0; index < 72; ++index) data += char(2 * (index % 24) + index / 24);
    writeBytes(file,
               "NRRD0004\ntype: uchar\ndimension: 4\nsizes: 4 3 2 3\nencoding: raw\n"
               "space dimension: 3\nspace directions: (0.5,0,0) (0,1,0) (0,0,2) none\nspace origin: (1,2,3)\n"
               "kinds: domain domain domain time\n\n" + data);
}

// bold.nii.gz: 3 x 2 x 2 voxels, 2 volumes, int16 value = index (0..23), voxel size 2 x 3 x 4, TR 2.5.
void writeNifti(const std::filesystem::path& file) {
    const std::int64_t dims[8] = {4, 3, 2, 2, 2, 1, 1, 1};
    nifti_image* image = nifti_make_new_nim(dims, DT_INT16, 1);
    if (image == nullptr) throw std::runtime_error("nifti_make_new_nim failed");
    image->dx = image->pixdim[1] = 2.0;
    image->dy = image->pixdim[2] = 3.0;
    image->dz = image->pixdim[3] = 4.0;
    image->dt = image->pixdim[4] = 2.5;
    auto* values = static_cast<std::int16_t*>(image->data);
    for (int index = 0; index < 24; ++index) values[index] = std::int16_t(index);
    if (nifti_set_filenames(image, file.c_str(), 0, 1) != 0) throw std::runtime_error("nifti_set_filenames failed");
    nifti_image_write(image);
    nifti_image_free(image);
}

// QCLOUDf01.bin .. f03.bin: 6 x 5 x 4 big-endian float32 (read with --dims 6x5x4), value = hour +
// index / 1000, the first 6 values (row y = 0, z = 0) the land marker 1.0e35.
void writeIsabel(const std::filesystem::path& folder) {
    for (int hour = 1; hour <= 3; ++hour) {
        std::string bytes;
        for (int index = 0; index < 120; ++index) {
            const float value = index < 6 ? 1.0e35f : float(hour) + float(index) / 1000.0f;
            const auto bits = std::bit_cast<std::uint32_t>(value);
            for (int shift = 24; shift >= 0; shift -= 8) bytes += char((bits >> shift) & 0xff);
        }
        char name[32];
        std::snprintf(name, sizeof name, "QCLOUDf%02d.bin", hour);
        writeBytes(folder / name, bytes);
    }
}

// classic.nc (CDF-1) and offset64.nc (CDF-2): temp(time 3, z 2, y 2, x 3) float over an unlimited
// time dimension, value = 100 t + index (0..11), with a time coordinate (hours 0, 1, 2). Two record
// variables, so every record is both slabs, each padded to 4 bytes: 8 + 48 bytes a record.
void writeClassic(const std::filesystem::path& file, int format) {
    int nc = 0, dims[4] = {}, temp = 0, time = 0;
    check(nc_create(file.c_str(), NC_CLOBBER | format, &nc), file.string());
    check(nc_def_dim(nc, "time", NC_UNLIMITED, &dims[0]), "time");
    const char* names[3] = {"z", "y", "x"};
    const std::size_t lengths[3] = {2, 2, 3};
    for (int axis = 0; axis < 3; ++axis) check(nc_def_dim(nc, names[axis], lengths[axis], &dims[axis + 1]), names[axis]);
    check(nc_def_var(nc, "time", NC_DOUBLE, 1, &dims[0], &time), "time var");
    check(nc_put_att_text(nc, time, "units", 24, "hours since 2000-01-01 0"), "units");
    check(nc_def_var(nc, "temp", NC_FLOAT, 4, dims, &temp), "temp");
    check(nc_enddef(nc), "enddef");
    const double times[3] = {0, 1, 2};
    const std::size_t start[1] = {0}, count[1] = {3};
    check(nc_put_vara_double(nc, time, start, count, times), "times");
    std::vector<float> values(36);
    for (std::size_t index = 0; index < values.size(); ++index) values[index] = float(100 * (index / 12) + index % 12);
    const std::size_t starts[4] = {0, 0, 0, 0}, counts[4] = {3, 2, 2, 3};
    check(nc_put_vara_float(nc, temp, starts, counts, values.data()), "temp values");
    check(nc_close(nc), "close");
}

// bigaxis.nc (netCDF-4, nothing written): v(time 1, z 2, y 2, x 1000000000) float; chunked, so
// the file stays small while its x axis is far too large to read.
void writeBigAxis(const std::filesystem::path& file) {
    int nc = 0, dims[4] = {}, variable = 0;
    check(nc_create(file.c_str(), NC_NETCDF4 | NC_CLOBBER, &nc), file.string());
    const char* names[4] = {"time", "z", "y", "x"};
    const std::size_t lengths[4] = {1, 2, 2, 1000000000};
    for (int axis = 0; axis < 4; ++axis) check(nc_def_dim(nc, names[axis], lengths[axis], &dims[axis]), names[axis]);
    check(nc_def_var(nc, "v", NC_FLOAT, 4, dims, &variable), "v");
    const std::size_t chunks[4] = {1, 2, 2, 1024};
    check(nc_def_var_chunking(nc, variable, NC_CHUNKED, chunks), "chunking");
    check(nc_close(nc), "close");
}

void appendBigEndian(std::string& bytes, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) bytes += char((value >> shift) & 0xff);
}

// A PNG chunk: length, type, data, and the CRC of type and data (zlib's crc32 is PNG's).
void appendPngChunk(std::string& png, const std::string& type, const std::string& data) {
    appendBigEndian(png, std::uint32_t(data.size()));
    const std::string typed = type + data;
    png += typed;
    appendBigEndian(png, std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(typed.data()), uInt(typed.size()))));
}

// huge.png: a valid PNG header (IHDR) announcing 1000000 x 1000000 RGBA pixels, followed by a few
// bytes of image data: what a damaged or hostile style image looks like.
void writeHugePng(const std::filesystem::path& file) {
    std::string png = "\x89PNG\r\n\x1a\n";
    std::string header;
    appendBigEndian(header, 1000000);
    appendBigEndian(header, 1000000);
    header += std::string("\x08\x06\x00\x00\x00", 5);  // 8 bits, RGBA, deflate, no filter, no interlace
    appendPngChunk(png, "IHDR", header);
    const std::string row(16, '\0');
    std::vector<Bytef> compressed(compressBound(uLong(row.size())));
    uLongf size = uLongf(compressed.size());
    if (compress(compressed.data(), &size, reinterpret_cast<const Bytef*>(row.data()), uLong(row.size())) != Z_OK)
        throw std::runtime_error("compress failed");
    appendPngChunk(png, "IDAT", std::string(reinterpret_cast<const char*>(compressed.data()), size));
    appendPngChunk(png, "IEND", "");
    writeBytes(file, png);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: write_reader_samples FOLDER\n";
        return 2;
    }
    try {
        const std::filesystem::path folder = argv[1];
        std::filesystem::create_directories(folder);
        writeOcean(folder / "ocean.nc");
        writeNoTime(folder / "notime.nc");
        writeWithOddValue(folder / "nan.nc", std::nanf(""));
        writeWithOddValue(folder / "inf.nc", std::numeric_limits<float>::infinity());
        writeInt64(folder / "int64.nc");
        writeNrrd(folder / "volume.nrrd");
        writeNifti(folder / "bold.nii.gz");
        writeIsabel(folder);
        writeClassic(folder / "classic.nc", 0);
        writeClassic(folder / "offset64.nc", NC_64BIT_OFFSET);
        writeBigAxis(folder / "bigaxis.nc");
        writeHugePng(folder / "huge.png");
    } catch (const std::exception& error) {
        std::cerr << "write_reader_samples: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
