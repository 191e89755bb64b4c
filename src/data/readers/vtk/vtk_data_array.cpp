// DataArray attributes and values: ascii numbers, inline base64 and appended data, every VTK scalar
// type in either byte order.
#include "vtk_data_array.h"

#include <charconv>
#include <algorithm>
#include <cmath>
#include <cstring>

#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

constexpr std::uint64_t kMaxComponents = 64;

std::optional<VtkValueType> valueTypeNamed(const std::string& name) {
    static const VtkValueType types[] = {
        {"Int8", VtkValueKind::Signed, 1},    {"UInt8", VtkValueKind::Unsigned, 1},
        {"Int16", VtkValueKind::Signed, 2},   {"UInt16", VtkValueKind::Unsigned, 2},
        {"Int32", VtkValueKind::Signed, 4},   {"UInt32", VtkValueKind::Unsigned, 4},
        {"Int64", VtkValueKind::Signed, 8},   {"UInt64", VtkValueKind::Unsigned, 8},
        {"Float32", VtkValueKind::Float, 4},  {"Float64", VtkValueKind::Float, 8}};
    for (const VtkValueType& type : types)
        if (type.name == name) return type;
    return std::nullopt;
}

std::string arrayField(const VtkXmlFile& file, const VtkDataArray& array) {
    return "DataArray '" + array.name + "' (line " + std::to_string(lineOf(file, array.node)) + ")";
}

std::vector<float> readAscii(const VtkXmlFile& file, const VtkDataArray& array, std::uint64_t count) {
    const std::string_view text = array.node.text().get();
    // Each number takes a character and a separator: a count beyond that is not in the file.
    if (count > text.size() / 2 + 1)
        throwInputError(file.path, arrayField(file, array),
                        "is truncated: " + std::to_string(count) + " numbers needed, the text holds fewer");
    std::vector<float> values(count);
    std::uint64_t found = 0;
    const char* position = text.data();
    const char* end = text.data() + text.size();
    while (true) {
        while (position < end && std::isspace(static_cast<unsigned char>(*position))) ++position;
        if (position == end) break;
        double value = 0.0;
        const auto [next, error] = std::from_chars(position, end, value);
        if (error != std::errc() || (next < end && !std::isspace(static_cast<unsigned char>(*next))))
            throwInputError(file.path, arrayField(file, array),
                            "'" + std::string(position, std::size_t(std::min<std::ptrdiff_t>(end - position, 20))) +
                                "' is not a number");
        if (found == count)
            throwInputError(file.path, arrayField(file, array),
                            "holds more than the " + std::to_string(count) + " numbers its extent needs");
        values[found++] = float(value);
        position = next;
    }
    if (found < count)
        throwInputError(file.path, arrayField(file, array),
                        "is truncated: " + std::to_string(found) + " of " + std::to_string(count) + " numbers");
    return values;
}

std::vector<float> readBinary(const VtkXmlFile& file, const VtkDataArray& array, std::uint64_t count) {
    std::string_view text;
    VtkByteStream::Encoding encoding = VtkByteStream::Encoding::Base64;
    if (array.format == "binary") {
        text = array.node.text().get();
    } else {
        if (!file.hasAppendedData)
            throwInputError(file.path, arrayField(file, array), "is appended, but the file has no <AppendedData>");
        if (array.offset > file.appended.size())
            throwInputError(file.path, arrayField(file, array),
                            "is truncated: its offset " + std::to_string(array.offset) + " lies beyond the " +
                                std::to_string(file.appended.size()) + " bytes of appended data");
        text = file.appended.substr(std::size_t(array.offset));
        encoding = file.appendedEncoding;
    }
    VtkByteStream stream(text, encoding);
    const std::vector<std::uint8_t> bytes =
        readVtkArrayBytes(stream, file.layout, count * array.type.bytes, file.path, arrayField(file, array));
    std::vector<float> values(count);
    for (std::uint64_t index = 0; index < count; ++index)
        values[index] = float(decodeVtkValue(bytes.data() + index * array.type.bytes, array.type, file.layout.bigEndian));
    return values;
}

std::vector<float> readComponents(const VtkXmlFile& file, const VtkDataArray& array, std::uint64_t tuples,
                                  std::uint64_t memoryCap) {
    const double count = double(tuples) * double(array.components);
    requireMemory(file.path, arrayField(file, array), count * double(4 + array.type.bytes), memoryCap,
                  "the values of one time-step");
    return array.format == "ascii" ? readAscii(file, array, std::uint64_t(count))
                                   : readBinary(file, array, std::uint64_t(count));
}

}  // namespace

std::string missingPointArrayProblem(const std::string& name, const std::string& pointArrayList,
                                     const std::vector<std::string>& cellArrays) {
    const std::string list = pointArrayList.empty() ? "none" : pointArrayList;
    if (std::find(cellArrays.begin(), cellArrays.end(), name) != cellArrays.end())
        return "'" + name + "' is a cell array: only point arrays are read (values at the grid's points); " +
               "the point arrays are: " + list;
    return "no point array named '" + name + "'; the point arrays are: " + list;
}

double decodeVtkValue(const std::uint8_t* bytes, const VtkValueType& type, bool bigEndian) {
    std::uint64_t bits = 0;
    for (std::size_t index = 0; index < type.bytes; ++index)
        bits |= std::uint64_t(bytes[bigEndian ? type.bytes - 1 - index : index]) << (8 * index);
    if (type.kind == VtkValueKind::Float) {
        if (type.bytes == 4) {
            float value;
            const auto narrow = std::uint32_t(bits);
            std::memcpy(&value, &narrow, 4);
            return value;
        }
        double value;
        std::memcpy(&value, &bits, 8);
        return value;
    }
    if (type.kind == VtkValueKind::Unsigned) return double(bits);
    const unsigned shift = unsigned(64 - 8 * type.bytes);  // sign-extend from the type's width
    return double(std::int64_t(bits << shift) >> shift);
}

std::vector<VtkDataArray> describeArrays(const VtkXmlFile& file, const pugi::xml_node& parent) {
    std::vector<VtkDataArray> arrays;
    for (const pugi::xml_node& node : parent.children("DataArray")) {
        VtkDataArray array;
        array.node = node;
        array.name = node.attribute("Name").as_string();
        if (array.name.empty()) array.name = "array " + std::to_string(arrays.size());
        const std::string typeName = node.attribute("type").as_string();
        const auto type = valueTypeNamed(typeName);
        if (!type)
            throwInputError(file.path, arrayField(file, array),
                            "unknown type '" + typeName + "' (known: Int8, UInt8, Int16, UInt16, Int32, UInt32, "
                                                          "Int64, UInt64, Float32, Float64)");
        array.type = *type;
        array.components = node.attribute("NumberOfComponents").as_ullong(1);
        if (array.components < 1 || array.components > kMaxComponents)
            throwInputError(file.path, arrayField(file, array),
                            "NumberOfComponents " + std::string(node.attribute("NumberOfComponents").as_string()) +
                                " is not between 1 and " + std::to_string(kMaxComponents));
        array.format = node.attribute("format").as_string("ascii");
        if (array.format != "ascii" && array.format != "binary" && array.format != "appended")
            throwInputError(file.path, arrayField(file, array),
                            "format '" + array.format + "' is none of ascii, binary, appended");
        if (array.format == "appended" && !node.attribute("offset"))
            throwInputError(file.path, arrayField(file, array), "appended data needs an offset");
        array.offset = node.attribute("offset").as_ullong(0);
        arrays.push_back(array);
    }
    return arrays;
}

ValueType seriesValueType(const VtkValueType& type) {
    if (type.name == "Int8") return ValueType::Int8;
    if (type.name == "UInt8") return ValueType::UInt8;
    if (type.name == "Int16") return ValueType::Int16;
    if (type.name == "UInt16") return ValueType::UInt16;
    if (type.name == "Int32") return ValueType::Int32;
    if (type.name == "Float32") return ValueType::Float32;
    return ValueType::Float64;
}

std::vector<float> readPointValues(const VtkXmlFile& file, const VtkDataArray& array, std::uint64_t tuples,
                                   std::uint64_t memoryCap) {
    std::vector<float> components = readComponents(file, array, tuples, memoryCap);
    if (array.components == 1) return components;
    std::vector<float> magnitudes(tuples);
    for (std::uint64_t tuple = 0; tuple < tuples; ++tuple) {
        double sum = 0.0;
        for (std::uint64_t component = 0; component < array.components; ++component) {
            const double value = components[tuple * array.components + component];
            sum += value * value;
        }
        magnitudes[tuple] = float(std::sqrt(sum));
    }
    return magnitudes;
}

std::vector<float> readPointComponents(const VtkXmlFile& file, const VtkDataArray& array, std::uint64_t tuples,
                                       std::uint64_t memoryCap) {
    return readComponents(file, array, tuples, memoryCap);
}

}  // namespace tstyles
