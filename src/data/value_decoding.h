// Decoding stored values of every ValueType in either byte order, whatever the host's order: the one
// byte-order decoder of the readers (values, and the unsigned integers of headers and markers).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tstyles/data/series.h"

namespace tstyles {

enum class ByteOrder { Little, Big };

// The unsigned integer of `size` bytes (1 to 8) starting at `bytes`.
std::uint64_t decodeUnsigned(const std::uint8_t* bytes, std::size_t size, ByteOrder order);

// One value of `type` starting at `bytes`.
double decodeValue(const std::uint8_t* bytes, ValueType type, ByteOrder order);

// `count` consecutive values as floats (float64 and int32 rounded to the nearest float).
std::vector<float> decodeValues(const std::uint8_t* bytes, std::size_t count, ValueType type, ByteOrder order);

}  // namespace tstyles
