// Byte-by-byte decoding keeps files portable: no reinterpret_cast of a buffer in the host's order.
#include "value_decoding.h"

#include <bit>

namespace tstyles {

std::uint64_t decodeUnsigned(const std::uint8_t* bytes, std::size_t size, ByteOrder order) {
    std::uint64_t bits = 0;
    for (std::size_t index = 0; index < size; ++index) {
        const std::size_t shift = order == ByteOrder::Little ? index : size - 1 - index;
        bits |= std::uint64_t(bytes[index]) << (8 * shift);
    }
    return bits;
}

double decodeValue(const std::uint8_t* bytes, ValueType type, ByteOrder order) {
    const std::uint64_t bits = decodeUnsigned(bytes, bytesPerValue(type), order);
    switch (type) {
        case ValueType::UInt8:
        case ValueType::UInt16:
            return double(bits);
        case ValueType::Int8:
            return double(std::int8_t(std::uint8_t(bits)));
        case ValueType::Int16:
            return double(std::int16_t(std::uint16_t(bits)));
        case ValueType::Int32:
            return double(std::int32_t(std::uint32_t(bits)));
        case ValueType::Float32:
            return double(std::bit_cast<float>(std::uint32_t(bits)));
        case ValueType::Float64:
            return std::bit_cast<double>(bits);
    }
    return 0.0;
}

std::vector<float> decodeValues(const std::uint8_t* bytes, std::size_t count, ValueType type, ByteOrder order) {
    std::vector<float> values(count);
    const std::size_t stride = bytesPerValue(type);
    for (std::size_t index = 0; index < count; ++index)
        values[index] = float(decodeValue(bytes + index * stride, type, order));
    return values;
}

}  // namespace tstyles
