// NRRD header parsing: magic line, "field: value" lines up to a blank line, then checks that the
// fields fit together (sizes per axis, an endian for multi-byte types, a data file that exists).
#include "nrrd_header.h"

#include <algorithm>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

std::string trim(const std::string& text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> words(const std::string& text) {
    std::istringstream stream(text);
    std::vector<std::string> result;
    for (std::string word; stream >> word;) result.push_back(word);
    return result;
}

std::optional<ValueType> nrrdType(const std::string& name) {
    static const std::map<std::string, ValueType> types = {
        {"signed char", ValueType::Int8},      {"int8", ValueType::Int8},
        {"int8_t", ValueType::Int8},           {"uchar", ValueType::UInt8},
        {"unsigned char", ValueType::UInt8},   {"uint8", ValueType::UInt8},
        {"uint8_t", ValueType::UInt8},         {"short", ValueType::Int16},
        {"short int", ValueType::Int16},       {"signed short", ValueType::Int16},
        {"signed short int", ValueType::Int16}, {"int16", ValueType::Int16},
        {"int16_t", ValueType::Int16},         {"ushort", ValueType::UInt16},
        {"unsigned short", ValueType::UInt16}, {"unsigned short int", ValueType::UInt16},
        {"uint16", ValueType::UInt16},         {"uint16_t", ValueType::UInt16},
        {"int", ValueType::Int32},             {"signed int", ValueType::Int32},
        {"int32", ValueType::Int32},           {"int32_t", ValueType::Int32},
        {"float", ValueType::Float32},         {"double", ValueType::Float64}};
    const auto found = types.find(name);
    if (found == types.end()) return std::nullopt;
    return found->second;
}

class HeaderFields {
public:
    HeaderFields(std::filesystem::path file, std::map<std::string, std::string> fields)
        : file_(std::move(file)), fields_(std::move(fields)) {}

    std::optional<std::string> get(std::initializer_list<const char*> names) const {
        for (const char* name : names) {
            const auto found = fields_.find(name);
            if (found != fields_.end()) return found->second;
        }
        return std::nullopt;
    }
    std::string require(const char* name) const {
        const auto value = get({name});
        if (!value) fail(name, "missing: a NRRD header must give it");
        return *value;
    }
    [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
        throwInputError(file_, field, problem);
    }
    double number(const std::string& field, const std::string& text) const {
        if (text == "nan" || text == "NaN") return std::numeric_limits<double>::quiet_NaN();
        std::size_t used = 0;
        try {
            const double value = std::stod(text, &used);
            if (used == text.size() && std::isfinite(value)) return value;
        } catch (const std::exception&) {
        }
        fail(field, "\"" + text + "\" is not a finite number");
    }
    // One number per axis: "spacings: 1 1 nan".
    std::vector<double> perAxis(const char* name, int dimension) const {
        std::vector<double> values(std::size_t(dimension), std::numeric_limits<double>::quiet_NaN());
        const auto text = get({name});
        if (!text) return values;
        const auto parts = words(*text);
        if (int(parts.size()) != dimension)
            fail(name, "expected " + std::to_string(dimension) + " values, found " + std::to_string(parts.size()));
        for (std::size_t axis = 0; axis < parts.size(); ++axis) values[axis] = number(name, parts[axis]);
        return values;
    }
    glm::dvec3 vector(const std::string& field, const std::string& text) const {
        // "(1.5,0,0)": three numbers between parentheses, separated by commas.
        if (text.size() < 2 || text.front() != '(' || text.back() != ')')
            fail(field, "expected a vector such as (1,0,0), found \"" + text + "\"");
        std::vector<double> parts;
        std::istringstream stream(text.substr(1, text.size() - 2));
        for (std::string part; std::getline(stream, part, ',');) parts.push_back(number(field, trim(part)));
        if (parts.size() != 3)
            fail(field, "expected 3 components (only 3D space is supported), found \"" + text + "\"");
        return {parts[0], parts[1], parts[2]};
    }

private:
    std::filesystem::path file_;
    std::map<std::string, std::string> fields_;
};

struct RawHeader {
    std::map<std::string, std::string> fields;
    std::uint64_t endOffset = 0;  // first byte after the blank line
};

RawHeader readRawHeader(const std::filesystem::path& file) {
    const std::uint64_t size = regularFileSize(file, "NRRD file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throwInputError(file, "", "cannot be opened for reading");
    std::string line;
    std::getline(in, line);
    if (line.rfind("NRRD000", 0) != 0 || line.size() < 8)
        throwInputError(file, "", "not a NRRD file: it does not start with the magic \"NRRD000N\"");
    RawHeader header;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) break;
        if (line[0] == '#' || line.find(":=") != std::string::npos) continue;  // comment, key/value pair
        const auto colon = line.find(": ");
        if (colon == std::string::npos) throwInputError(file, "", "header line \"" + line + "\" is not \"field: value\"");
        header.fields[line.substr(0, colon)] = trim(line.substr(colon + 2));
        if (header.fields.size() > 1000) throwInputError(file, "", "header has too many fields");
    }
    header.endOffset = in.eof() ? size : std::uint64_t(in.tellg());
    return header;
}

void readDirections(const HeaderFields& fields, NrrdHeader& header) {
    header.directions.assign(std::size_t(header.dimension), std::nullopt);
    const auto text = fields.get({"space directions"});
    if (!text) return;
    const auto parts = words(*text);
    if (int(parts.size()) != header.dimension)
        fields.fail("space directions", "expected " + std::to_string(header.dimension) + " entries (a vector or none per axis), found " +
                                            std::to_string(parts.size()));
    for (std::size_t axis = 0; axis < parts.size(); ++axis)
        if (parts[axis] != "none") header.directions[axis] = fields.vector("space directions", parts[axis]);
    if (const auto origin = fields.get({"space origin"})) header.origin = fields.vector("space origin", *origin);
    if (const auto space = fields.get({"space"})) header.space = *space;
    if (const auto units = fields.get({"space units"}))
        for (std::string unit : words(*units)) {
            unit.erase(std::remove(unit.begin(), unit.end(), '"'), unit.end());
            header.spaceUnits.push_back(unit);
        }
}

void readDataLocation(const HeaderFields& fields, const RawHeader& raw, NrrdHeader& header) {
    const auto detached = fields.get({"data file", "datafile"});
    header.dataFile = header.headerFile;
    header.dataOffset = raw.endOffset;
    if (detached) {
        if (detached->rfind("LIST", 0) == 0 || words(*detached).size() > 1)
            fields.fail("data file", "lists of data files are not supported: give one file per header");
        const std::filesystem::path name = *detached;
        header.dataFile = name.is_absolute() ? name : header.headerFile.parent_path() / name;
        header.dataOffset = 0;
    }
    // Whatever the header says, the data file must be one we can read to its end: a folder or a
    // device here would surface later as a filesystem error, or block.
    requireRegularFile(header.dataFile, "NRRD data file");
    const std::uint64_t dataFileSize = regularFileSize(header.dataFile, "NRRD data file");
    const auto skip = [&](const char* name, std::initializer_list<const char*> spellings) -> std::int64_t {
        const auto text = fields.get(spellings);
        if (!text) return 0;
        const double value = fields.number(name, *text);
        if (value != std::floor(value) || value < -1.0 || value > double(dataFileSize))
            fields.fail(name, "\"" + *text + "\" is not a count between -1 and the data file's " +
                                  std::to_string(dataFileSize) + " bytes");
        return std::int64_t(value);
    };
    const std::int64_t lineSkip = skip("line skip", {"line skip", "lineskip"});
    const std::int64_t byteSkip = skip("byte skip", {"byte skip", "byteskip"});
    if (lineSkip < 0) fields.fail("line skip", "must not be negative");
    if (header.encoding == DataEncoding::Gzip && byteSkip != 0)
        fields.fail("byte skip", "is not supported with gzip encoding");
    if (lineSkip > 0) {
        std::ifstream in(header.dataFile, std::ios::binary);
        in.seekg(std::streamoff(header.dataOffset));
        std::string skipped;
        for (std::int64_t line = 0; line < lineSkip; ++line)
            if (!std::getline(in, skipped)) fields.fail("line skip", "the data file has fewer lines than skipped");
        header.dataOffset = std::uint64_t(in.tellg());
    }
    header.dataAtEnd = byteSkip == -1;
    if (byteSkip > 0) header.dataOffset += std::uint64_t(byteSkip);
}

}  // namespace

NrrdHeader readNrrdHeader(const std::filesystem::path& file) {
    const RawHeader raw = readRawHeader(file);
    const HeaderFields fields(file, raw.fields);
    NrrdHeader header;
    header.headerFile = file;

    const std::string typeName = fields.require("type");
    const auto type = nrrdType(typeName);
    if (!type)
        fields.fail("type", "unsupported type \"" + typeName +
                                "\" (supported: int8, uint8, int16, uint16, int32, float, double)");
    header.type = *type;

    const std::string dimension = fields.require("dimension");
    if (dimension != "3" && dimension != "4")
        fields.fail("dimension", "must be 3 (a volume) or 4 (a volume series), found \"" + dimension + "\"");
    header.dimension = dimension == "3" ? 3 : 4;
    const auto sizes = words(fields.require("sizes"));
    if (int(sizes.size()) != header.dimension)
        fields.fail("sizes", "expected " + std::to_string(header.dimension) + " sizes, found " + std::to_string(sizes.size()));
    for (const std::string& size : sizes) {
        const double value = fields.number("sizes", size);
        if (value < 1 || value > 1e6 || value != std::floor(value)) fields.fail("sizes", "\"" + size + "\" is not a size");
        header.sizes.push_back(std::int64_t(value));
    }

    const std::string encoding = fields.require("encoding");
    if (encoding == "raw") header.encoding = DataEncoding::Raw;
    else if (encoding == "gzip" || encoding == "gz") header.encoding = DataEncoding::Gzip;
    else fields.fail("encoding", "unsupported encoding \"" + encoding + "\" (supported: raw, gzip)");

    if (bytesPerValue(header.type) > 1) {
        const auto endian = fields.get({"endian"});
        if (!endian) fields.fail("endian", "missing: required for multi-byte types");
        if (*endian == "little") header.byteOrder = ByteOrder::Little;
        else if (*endian == "big") header.byteOrder = ByteOrder::Big;
        else fields.fail("endian", "expected little or big, found \"" + *endian + "\"");
    }

    readDirections(fields, header);
    header.spacings = fields.perAxis("spacings", header.dimension);
    header.axisMins = fields.perAxis("axis mins", header.dimension);
    if (const auto kinds = fields.get({"kinds"})) {
        header.kinds = words(*kinds);
        if (int(header.kinds.size()) != header.dimension)
            fields.fail("kinds", "expected " + std::to_string(header.dimension) + " kinds, found " +
                                     std::to_string(header.kinds.size()));
    } else {
        header.kinds.assign(std::size_t(header.dimension), "");
    }
    readDataLocation(fields, raw, header);
    return header;
}

}  // namespace tstyles
