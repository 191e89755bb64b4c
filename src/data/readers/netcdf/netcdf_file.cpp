// Thin checked calls into libnetcdf.
#include "netcdf_file.h"

#include <cmath>

#include <netcdf.h>

#include "netcdf_classic_check.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"
#include "tstyles/core/stderr_capture.h"

namespace tstyles {

NetcdfFile::NetcdfFile(std::filesystem::path file, ReadingMonitor* monitor)
    : path_(std::move(file)), monitor_(monitor) {
    const std::uint64_t bytes = regularFileSize(path_, "NetCDF file");
    // A classic header is only handed to the library once its counts and sizes fit the file;
    // netCDF-4 (HDF5) files are checked by the library, whose HDF5 error stack we capture.
    if (hasClassicNetcdfMagic(path_)) checkClassicNetcdf(path_);
    const StderrCapture libraryMessages;
    enterStage("opening the file");
    const int status = nc_open(path_.c_str(), NC_NOWRITE, &id_);
    if (status != NC_NOERR) {
        id_ = -1;
        throwInputError(path_, "",
                        "not a readable NetCDF file (truncated or damaged? " + std::to_string(bytes) +
                            " bytes): " + nc_strerror(status));
    }
}

NetcdfFile::~NetcdfFile() {
    if (id_ >= 0) nc_close(id_);
}

void NetcdfFile::check(int status, const std::string& field, const std::string& doing) const {
    // An HDF5 read error in a netCDF-4 file is most often a cut or damaged file.
    if (status == NC_EHDFERR)
        throwInputError(path_, field, "cannot " + doing + ": the file is truncated or damaged (" + nc_strerror(status) + ")");
    if (status != NC_NOERR) throwInputError(path_, field, "cannot " + doing + ": " + nc_strerror(status));
}

std::string NetcdfFile::formatName() const {
    int format = 0;
    enterStage("reading the format");
    check(nc_inq_format(id_, &format), "", "read the format");
    switch (format) {
        case NC_FORMAT_CLASSIC:
            return "NetCDF classic";
        case NC_FORMAT_64BIT_OFFSET:
            return "NetCDF 64-bit offset";
        case NC_FORMAT_64BIT_DATA:
            return "NetCDF 64-bit data";
        case NC_FORMAT_NETCDF4:
            return "NetCDF-4";
        case NC_FORMAT_NETCDF4_CLASSIC:
            return "NetCDF-4 classic model";
        default:
            return "NetCDF";
    }
}

std::vector<int> NetcdfFile::variableIds() const {
    int count = 0;
    enterStage("reading the variable list");
    check(nc_inq_nvars(id_, &count), "", "count the variables");
    std::vector<int> ids(static_cast<std::size_t>(count));
    for (int index = 0; index < count; ++index) ids[std::size_t(index)] = index;
    return ids;
}

std::optional<int> NetcdfFile::findVariable(const std::string& name) const {
    int id = 0;
    enterStage("reading the variable list");
    if (nc_inq_varid(id_, name.c_str(), &id) != NC_NOERR) return std::nullopt;
    return id;
}

NetcdfVariable NetcdfFile::variable(int id) const {
    NetcdfVariable variable;
    variable.id = id;
    char name[NC_MAX_NAME + 1] = {};
    int dimensionCount = 0;
    enterStage("reading the variable list");
    check(nc_inq_var(id_, id, name, &variable.type, &dimensionCount, nullptr, nullptr), "", "read a variable");
    variable.name = name;
    std::vector<int> dimensionIds(static_cast<std::size_t>(dimensionCount));
    check(nc_inq_vardimid(id_, id, dimensionIds.data()), variable.name, "read its dimensions");
    for (int dimensionId : dimensionIds) {
        NetcdfDimension dimension;
        dimension.id = dimensionId;
        char dimensionName[NC_MAX_NAME + 1] = {};
        check(nc_inq_dim(id_, dimensionId, dimensionName, &dimension.length), variable.name, "read a dimension");
        dimension.name = dimensionName;
        variable.dimensions.push_back(dimension);
    }
    return variable;
}

bool NetcdfFile::isCoordinateVariable(int id) const {
    const NetcdfVariable candidate = variable(id);
    return candidate.dimensions.size() == 1 && candidate.dimensions[0].name == candidate.name &&
           candidate.type != NC_CHAR && candidate.type != NC_STRING;
}

std::optional<std::string> NetcdfFile::textAttribute(int variable, const std::string& name) const {
    nc_type type = 0;
    std::size_t length = 0;
    enterStage("reading the attributes");
    if (nc_inq_att(id_, variable, name.c_str(), &type, &length) != NC_NOERR || type != NC_CHAR) return std::nullopt;
    std::string text(length, '\0');
    check(nc_get_att_text(id_, variable, name.c_str(), text.data()), name, "read the attribute");
    while (!text.empty() && text.back() == '\0') text.pop_back();
    return text;
}

std::optional<std::vector<double>> NetcdfFile::numberAttribute(int variable, const std::string& name) const {
    nc_type type = 0;
    std::size_t length = 0;
    enterStage("reading the attributes");
    if (nc_inq_att(id_, variable, name.c_str(), &type, &length) != NC_NOERR) return std::nullopt;
    if (type == NC_CHAR || type == NC_STRING || length == 0)
        throwInputError(path_, name, "attribute must be numeric");
    std::vector<double> values(length);
    check(nc_get_att_double(id_, variable, name.c_str(), values.data()), name, "read the attribute");
    return values;
}

std::vector<double> NetcdfFile::readAll(int id) const {
    const NetcdfVariable whole = variable(id);
    std::size_t count = 1;
    for (const auto& dimension : whole.dimensions) count *= dimension.length;
    if (count > std::size_t(1) << 26)
        throwInputError(path_, whole.name, "has " + std::to_string(count) + " values: too many for a coordinate variable");
    std::vector<double> values(count);
    const StderrCapture libraryMessages;
    enterStage("reading the coordinates");
    check(nc_get_var_double(id_, id, values.data()), whole.name, "read the values");
    return values;
}

NetcdfPacking NetcdfFile::packing(const NetcdfVariable& variable) const {
    NetcdfPacking packing;
    const auto single = [&](const char* name) -> std::optional<double> {
        const auto values = numberAttribute(variable.id, name);
        if (!values) return std::nullopt;
        if (values->size() != 1) throwInputError(path_, variable.name + "." + name, "expected one number");
        return values->front();
    };
    // Without _FillValue the library's default fill marks unwritten floats; other types' defaults
    // (255 for ubyte, -127 for byte ...) are too often real data to be assumed missing.
    auto fill = single("_FillValue");
    if (!fill && variable.type == NC_FLOAT) fill = double(NC_FILL_FLOAT);
    if (!fill && variable.type == NC_DOUBLE) fill = NC_FILL_DOUBLE;
    if (fill) packing.missingValues.push_back(*fill);
    if (const auto missing = numberAttribute(variable.id, "missing_value"))
        packing.missingValues.insert(packing.missingValues.end(), missing->begin(), missing->end());
    for (double value : packing.missingValues) packing.nanIsMissing = packing.nanIsMissing || std::isnan(value);
    packing.scale = single("scale_factor").value_or(1.0);
    packing.offset = single("add_offset").value_or(0.0);
    if (!std::isfinite(packing.scale) || !std::isfinite(packing.offset))
        throwInputError(path_, variable.name, "scale_factor and add_offset must be finite");
    // Stored floats compare in their own precision: a float variable's fill read as double is exact,
    // but the attribute may have been written as double.
    if (variable.type == NC_FLOAT)
        for (double& value : packing.missingValues) value = double(float(value));
    return packing;
}

NetcdfVolume NetcdfFile::readVolume(const NetcdfVariable& variable, int timeDimension, std::size_t timeIndex,
                                    const NetcdfPacking& packing) const {
    std::vector<std::size_t> start(variable.dimensions.size(), 0);
    std::vector<std::size_t> count;
    std::size_t total = 1;
    for (std::size_t index = 0; index < variable.dimensions.size(); ++index) {
        const bool isTime = int(index) == timeDimension;
        count.push_back(isTime ? 1 : variable.dimensions[index].length);
        if (isTime) start[index] = timeIndex;
        total *= count.back();
    }
    std::vector<double> stored(total);
    const StderrCapture libraryMessages;
    enterStage("reading the values");
    check(nc_get_vara_double(id_, variable.id, start.data(), count.data(), stored.data()), variable.name,
          "read time index " + std::to_string(timeIndex));
    NetcdfVolume volume;
    volume.values.resize(total);
    volume.missing.assign(total, false);
    for (std::size_t index = 0; index < total; ++index) {
        const double value = stored[index];
        bool missing = packing.nanIsMissing && std::isnan(value);
        for (double marker : packing.missingValues) missing = missing || value == marker;
        if (missing) {
            volume.missing[index] = true;
            continue;
        }
        volume.values[index] = float(value * packing.scale + packing.offset);
    }
    return volume;
}

ValueType netcdfValueType(const NetcdfFile& file, const NetcdfVariable& variable) {
    switch (variable.type) {
        case NC_BYTE:
            return ValueType::Int8;
        case NC_UBYTE:
            return ValueType::UInt8;
        case NC_SHORT:
            return ValueType::Int16;
        case NC_USHORT:
            return ValueType::UInt16;
        case NC_INT:
            return ValueType::Int32;
        case NC_FLOAT:
            return ValueType::Float32;
        case NC_DOUBLE:
            return ValueType::Float64;
        default:
            throwInputError(file.path(), variable.name,
                            "unsupported value type (nc_type " + std::to_string(variable.type) +
                                "; supported: byte, ubyte, short, ushort, int, float, double)");
    }
}

}  // namespace tstyles
