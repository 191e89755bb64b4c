// Decoding stored values of every ValueType in either byte order, whatever the host's order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tstyles/data/series.h"

namespace tstyles {

enum class ByteOrder { Little, Big };

// One value of `type` starting at `bytes`.
double decodeValue(const std::uint8_t* bytes, ValueType type, ByteOrder order);

// `count` consecutive values as floats (float64 and int32 rounded to the nearest float).
std::vector<float> decodeValues(const std::uint8_t* bytes, std::size_t count, ValueType type, ByteOrder order);

}  // namespace tstyles
