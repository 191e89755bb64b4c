// Intervals of numbers and the shortest text of a number.
#include "tstyles/core/interval.h"

#include <charconv>
#include <cmath>

namespace tstyles {

std::string formatNumber(double value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

bool Interval::contains(double value) const {
    const bool aboveLow = lowIncluded ? value >= low : value > low;
    const bool belowHigh = highIncluded ? value <= high : value < high;
    return aboveLow && belowHigh;
}

std::string Interval::refusal(double value) const {
    return "must be " + describe() + ", got " + formatNumber(value);
}

std::string Interval::describe() const {
    if (std::isinf(high) && std::isinf(low)) return "finite";
    if (std::isinf(high)) return (lowIncluded ? ">= " : "> ") + formatNumber(low);
    return std::string("in ") + (lowIncluded ? "[" : "(") + formatNumber(low) + ", " + formatNumber(high) +
           (highIncluded ? "]" : ")");
}

}  // namespace tstyles
