// The values a number may take, and how a number is written in messages and files: what every
// reader checks a number against (json_field.h), the scene key table (scene_keys.h) and the
// compositors' options (temporal_compositors.h) hold.
#pragma once

#include <limits>
#include <string>

namespace tstyles {

// Shortest text that reads back as the same double ("0.1", "1e+300", "inf").
std::string formatNumber(double value);

// The values a number may take; either end may be open, and `high` may be +infinity.
struct Interval {
    double low;
    double high;
    bool lowIncluded = true;
    bool highIncluded = true;

    bool contains(double value) const;
    // Why `value` is not one of them: "must be in [0, 1], got 1.5" (every reader's wording).
    std::string refusal(double value) const;
    // "in [0, 1]", "in (0, 180)", "> 0", ">= 0", "finite".
    std::string describe() const;
};

// Any finite number (finiteness is checked before the interval).
inline constexpr Interval anyFinite{-std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::infinity()};
inline constexpr Interval unitInterval{0.0, 1.0};
inline constexpr Interval aboveZero{0.0, std::numeric_limits<double>::infinity(), false};

}  // namespace tstyles
