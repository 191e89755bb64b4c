// The classic NetCDF header, walked by the format specification (NetCDF Users Guide, "File
// Format Specifications"), with every count bounded by the bytes left before it is believed.
#include "netcdf_classic_check.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

constexpr std::uint32_t kDimensionTag = 0x0A;
constexpr std::uint32_t kVariableTag = 0x0B;
constexpr std::uint32_t kAttributeTag = 0x0C;
constexpr std::uint32_t kMaxName = 256;  // NC_MAX_NAME

struct ClassicVariable {
    std::string name;
    std::vector<std::uint64_t> dimensionIds;
    std::uint64_t begin = 0;
    std::uint64_t valueBytes = 0;
};

struct ClassicHeader {
    std::uint64_t recordCount = 0;
    bool streaming = false;  // record count not recorded: the library derives it from the size
    std::vector<std::uint64_t> dimensionLengths;  // 0: the record dimension
    std::vector<ClassicVariable> variables;
    std::uint64_t end = 0;
};

// Bytes of one value of an nc_type; 0 for a type the format does not have.
std::uint64_t typeBytes(std::uint32_t type, int version) {
    static constexpr std::array<std::uint64_t, 12> kBytes{0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
    const std::uint32_t lastType = version == 5 ? 11 : 6;
    return type >= 1 && type <= lastType ? kBytes[type] : 0;
}

std::uint64_t padded(std::uint64_t bytes) { return (bytes + 3) / 4 * 4; }

// a * b, or UINT64_MAX when it overflows: far beyond any file, which is all a size check needs.
std::uint64_t saturatingProduct(std::uint64_t a, std::uint64_t b) {
    if (a != 0 && b > UINT64_MAX / a) return UINT64_MAX;
    return a * b;
}

class HeaderReader {
public:
    HeaderReader(const std::filesystem::path& file, std::uint64_t size, int version)
        : file_(file), size_(size), version_(version), in_(file, std::ios::binary) {
        if (!in_) throwInputError(file_, "", "cannot be opened for reading");
        position_ = 4;
        in_.seekg(4);
    }

    std::uint64_t position() const { return position_; }
    std::uint64_t left() const { return size_ - position_; }
    int version() const { return version_; }

    [[noreturn]] void truncated(const std::string& field, std::uint64_t needed) const {
        throwInputError(file_, field,
                        "is truncated: the NetCDF header needs " + std::to_string(needed) + " bytes from byte " +
                            std::to_string(position_) + ", the file has only " + std::to_string(left()) +
                            " bytes left (" + std::to_string(size_) + " in all)");
    }
    [[noreturn]] void damaged(const std::string& field, const std::string& problem) const {
        throwInputError(file_, field, "damaged NetCDF header at byte " + std::to_string(position_) + ": " + problem);
    }

    std::uint64_t integer(const std::string& field, int bytes) {
        if (left() < std::uint64_t(bytes)) truncated(field, std::uint64_t(bytes));
        unsigned char raw[8] = {};
        in_.read(reinterpret_cast<char*>(raw), bytes);
        if (!in_) damaged(field, "cannot be read");
        position_ += std::uint64_t(bytes);
        std::uint64_t value = 0;
        for (int index = 0; index < bytes; ++index) value = value << 8 | raw[index];  // big-endian
        return value;
    }
    std::uint32_t word(const std::string& field) { return std::uint32_t(integer(field, 4)); }
    // NON_NEG: 32 bits, 64 in CDF-5; a 32-bit one with the sign bit set is damage.
    std::uint64_t count(const std::string& field) {
        const std::uint64_t value = integer(field, version_ == 5 ? 8 : 4);
        if (version_ != 5 && value > 0x7fffffffu) damaged(field, "negative count " + std::to_string(std::int32_t(value)));
        return value;
    }
    std::uint64_t offset(const std::string& field) { return integer(field, version_ == 1 ? 4 : 8); }

    void skip(const std::string& field, std::uint64_t bytes) {
        if (left() < bytes) truncated(field, bytes);
        position_ += bytes;
        in_.seekg(std::streamoff(position_));
    }
    std::string name(const std::string& field) {
        const std::uint64_t length = count(field + " name length");
        if (length == 0 || length > kMaxName)
            damaged(field, "a name of " + std::to_string(length) + " bytes (1 to 256 allowed)");
        if (left() < padded(length)) truncated(field + " name", padded(length));
        std::string text(std::size_t(length), '\0');
        in_.read(text.data(), std::streamsize(length));
        if (!in_) damaged(field, "cannot be read");
        position_ += length;
        skip(field, padded(length) - length);
        return text;
    }
    // A list's tag and element count, with the count bounded by the bytes its elements need.
    std::uint64_t listCount(std::uint32_t tag, const std::string& field, std::uint64_t minimumElementBytes) {
        const std::uint32_t found = word(field);
        const std::uint64_t elements = count(field + " count");
        if (found == 0 && elements == 0) return 0;  // ABSENT
        if (found != tag) damaged(field, "expected list tag " + std::to_string(tag) + ", found " + std::to_string(found));
        if (elements > left() / minimumElementBytes)
            damaged(field, "the header says " + std::to_string(elements) + " entries, which need at least " +
                               std::to_string(saturatingProduct(elements, minimumElementBytes)) +
                               " bytes, but only " + std::to_string(left()) + " bytes are left in the file");
        return elements;
    }

private:
    const std::filesystem::path& file_;
    std::uint64_t size_;
    int version_;
    std::ifstream in_;
    std::uint64_t position_ = 0;
};

void skipAttributes(HeaderReader& reader, const std::string& owner) {
    const std::uint64_t attributes =
        reader.listCount(kAttributeTag, owner.empty() ? "attributes" : owner + " attributes", 16);
    for (std::uint64_t index = 0; index < attributes; ++index) {
        const std::string name = reader.name(owner + " attribute " + std::to_string(index));
        const std::string field = owner.empty() ? name : owner + "." + name;
        const std::uint32_t type = reader.word(field + " type");
        const std::uint64_t size = typeBytes(type, reader.version());
        if (size == 0) reader.damaged(field, "unknown attribute type " + std::to_string(type));
        const std::uint64_t values = reader.count(field + " length");
        const std::uint64_t bytes = saturatingProduct(values, size);
        if (bytes > reader.left()) reader.truncated(field, bytes);
        reader.skip(field, padded(bytes));
    }
}

ClassicVariable readVariable(HeaderReader& reader, const ClassicHeader& header, std::uint64_t index) {
    ClassicVariable variable;
    variable.name = reader.name("variable " + std::to_string(index));
    const std::uint64_t rank = reader.count(variable.name + " rank");
    if (rank > reader.left() / 4) reader.truncated(variable.name + " dimensions", saturatingProduct(rank, 4));
    for (std::uint64_t axis = 0; axis < rank; ++axis) {
        const std::uint64_t id = reader.count(variable.name + " dimension id");
        if (id >= header.dimensionLengths.size())
            reader.damaged(variable.name, "dimension id " + std::to_string(id) + " of " +
                                              std::to_string(header.dimensionLengths.size()) + " dimensions");
        if (axis > 0 && header.dimensionLengths[id] == 0)
            reader.damaged(variable.name, "only the first dimension may be the record dimension");
        variable.dimensionIds.push_back(id);
    }
    skipAttributes(reader, variable.name);
    const std::uint32_t type = reader.word(variable.name + " type");
    const std::uint64_t size = typeBytes(type, reader.version());
    if (size == 0) reader.damaged(variable.name, "unknown variable type " + std::to_string(type));
    reader.count(variable.name + " size");  // vsize: recomputed below, as the library does for large variables
    variable.begin = reader.offset(variable.name + " begin");
    variable.valueBytes = size;
    return variable;
}

ClassicHeader readHeader(HeaderReader& reader) {
    ClassicHeader header;
    const std::uint64_t records = reader.integer("numrecs", reader.version() == 5 ? 8 : 4);
    header.streaming = records == (reader.version() == 5 ? UINT64_MAX : 0xffffffffu);
    if (!header.streaming && reader.version() != 5 && records > 0x7fffffffu)
        reader.damaged("numrecs", "negative record count");
    header.recordCount = header.streaming ? 0 : records;
    const std::uint64_t dimensions = reader.listCount(kDimensionTag, "dimensions", 12);
    for (std::uint64_t index = 0; index < dimensions; ++index) {
        const std::string name = reader.name("dimension " + std::to_string(index));
        header.dimensionLengths.push_back(reader.count(name + " length"));
    }
    if (std::count(header.dimensionLengths.begin(), header.dimensionLengths.end(), 0) > 1)
        reader.damaged("dimensions", "more than one record (unlimited) dimension");
    skipAttributes(reader, "");
    const std::uint64_t variables = reader.listCount(kVariableTag, "variables", 32);
    for (std::uint64_t index = 0; index < variables; ++index)
        header.variables.push_back(readVariable(reader, header, index));
    header.end = reader.position();
    return header;
}

bool isRecordVariable(const ClassicHeader& header, const ClassicVariable& variable) {
    return !variable.dimensionIds.empty() && header.dimensionLengths[variable.dimensionIds.front()] == 0;
}

// Bytes of one record of a record variable, or of the whole of any other variable.
std::uint64_t slabBytes(const ClassicHeader& header, const ClassicVariable& variable) {
    std::uint64_t bytes = variable.valueBytes;
    for (std::uint64_t id : variable.dimensionIds)
        if (header.dimensionLengths[id] != 0) bytes = saturatingProduct(bytes, header.dimensionLengths[id]);
    return bytes;
}

void checkDataExtents(const std::filesystem::path& file, const ClassicHeader& header, std::uint64_t size) {
    // Records interleave every record variable; each slab is padded to 4 bytes unless there is
    // only one record variable (the format's special case).
    std::vector<const ClassicVariable*> recordVariables;
    for (const ClassicVariable& variable : header.variables)
        if (isRecordVariable(header, variable)) recordVariables.push_back(&variable);
    std::uint64_t recordBytes = 0;
    for (const ClassicVariable* variable : recordVariables) {
        const std::uint64_t slab = slabBytes(header, *variable);
        recordBytes = std::min(UINT64_MAX - 4, recordBytes) + (recordVariables.size() == 1 ? slab : padded(slab));
    }
    for (const ClassicVariable& variable : header.variables) {
        if (variable.begin < header.end)
            throwInputError(file, variable.name,
                            "damaged NetCDF header: the data begins at byte " + std::to_string(variable.begin) +
                                ", inside the header (which ends at byte " + std::to_string(header.end) + ")");
        const std::uint64_t slab = slabBytes(header, variable);
        const bool record = isRecordVariable(header, variable);
        if (record && (header.streaming || header.recordCount == 0)) continue;
        const std::uint64_t lastStart =
            record ? variable.begin + std::min(saturatingProduct(header.recordCount - 1, recordBytes),
                                               UINT64_MAX - variable.begin)
                   : variable.begin;
        const std::uint64_t end = lastStart + std::min(slab, UINT64_MAX - lastStart);  // saturating
        if (end <= size) continue;
        // The first record that does not fit: the time-step from which the data is missing.
        std::string where = "its data (" + std::to_string(slab) + " bytes from byte " + std::to_string(variable.begin) + ")";
        if (record) {
            const std::uint64_t fitting = size < variable.begin || size - variable.begin < slab || recordBytes == 0
                                              ? 0
                                              : (size - variable.begin - slab) / recordBytes + 1;
            where = "time-step " + std::to_string(fitting) + " of " + std::to_string(header.recordCount) +
                    " (counting from 0; a record of " + std::to_string(slab) + " bytes every " +
                    std::to_string(recordBytes) + " bytes from byte " + std::to_string(variable.begin) + ")";
        }
        throwInputError(file, variable.name,
                        "is truncated: " + where + " needs the file to reach byte " +
                            (end == UINT64_MAX ? std::string("beyond 2^64") : std::to_string(end)) +
                            ", the file has only " + std::to_string(size) + " bytes");
    }
}

}  // namespace

bool hasClassicNetcdfMagic(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    return in && magic[0] == 'C' && magic[1] == 'D' && magic[2] == 'F' && (magic[3] == 1 || magic[3] == 2 || magic[3] == 5);
}

void checkClassicNetcdf(const std::filesystem::path& file) {
    const std::uint64_t size = regularFileSize(file, "NetCDF file");
    char magic[4] = {};
    std::ifstream(file, std::ios::binary).read(magic, 4);
    HeaderReader reader(file, size, magic[3]);
    const ClassicHeader header = readHeader(reader);
    checkDataExtents(file, header, size);
}

}  // namespace tstyles
