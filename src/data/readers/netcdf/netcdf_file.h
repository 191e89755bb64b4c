// A NetCDF file open for reading (RAII over nc_open/nc_close), with the few queries the reader
// needs; every library error becomes an InputError naming the file and what was being read.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/data/reading_monitor.h"
#include "tstyles/data/series.h"

namespace tstyles {

struct NetcdfDimension {
    int id = 0;
    std::string name;
    std::size_t length = 0;
};

struct NetcdfVariable {
    int id = 0;
    std::string name;
    int type = 0;  // nc_type
    std::vector<NetcdfDimension> dimensions;  // slowest first
};

// How stored values become data: which are missing, and the linear unpacking.
struct NetcdfPacking {
    std::vector<double> missingValues;  // _FillValue, missing_value (in the stored type's precision)
    bool nanIsMissing = false;          // a declared marker is NaN
    double scale = 1.0;
    double offset = 0.0;
};

struct NetcdfVolume {
    std::vector<float> values;  // unpacked; 0 where missing
    std::vector<bool> missing;
};

class NetcdfFile {
public:
    // `monitor` (may be null) hears each stage before the library is called for it.
    explicit NetcdfFile(std::filesystem::path file, ReadingMonitor* monitor = nullptr);
    ~NetcdfFile();
    NetcdfFile(const NetcdfFile&) = delete;
    NetcdfFile& operator=(const NetcdfFile&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::string formatName() const;
    std::vector<int> variableIds() const;
    std::optional<int> findVariable(const std::string& name) const;
    NetcdfVariable variable(int id) const;
    // A one-dimensional numeric variable named like its dimension (CF coordinate variable).
    bool isCoordinateVariable(int id) const;
    std::optional<std::string> textAttribute(int variable, const std::string& name) const;
    std::optional<std::vector<double>> numberAttribute(int variable, const std::string& name) const;
    std::vector<double> readAll(int variable) const;  // a whole (small) variable as doubles
    NetcdfPacking packing(const NetcdfVariable& variable) const;
    // The three spatial dimensions at one index of the time dimension (none: timeDimension < 0).
    NetcdfVolume readVolume(const NetcdfVariable& variable, int timeDimension, std::size_t timeIndex,
                            const NetcdfPacking& packing) const;

private:
    void check(int status, const std::string& field, const std::string& doing) const;
    void enterStage(std::string_view doing) const { reportStage(monitor_, path_, kLibrary, doing); }

    static constexpr std::string_view kLibrary = "the NetCDF/HDF5 library";
    std::filesystem::path path_;
    ReadingMonitor* monitor_ = nullptr;
    int id_ = -1;
};

// Our value type for a variable's stored type; unsupported types are an InputError.
ValueType netcdfValueType(const NetcdfFile& file, const NetcdfVariable& variable);

}  // namespace tstyles
