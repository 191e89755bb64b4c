// Units of spatial axes as files spell them (CF/UDUNITS names, NIfTI and NRRD units), reduced to a
// kind and a factor to that kind's base unit, so that "km" and "m" count as one kind of unit and
// "degrees_east" and "m" do not. Private to src/data.
#pragma once

#include <string>

namespace tstyles {

enum class UnitKind { None, Length, Angle, Pressure, Other };

struct AxisUnit {
    UnitKind kind = UnitKind::None;
    double toBase = 1.0;  // metres, degrees or pascals per unit; 1 for None and Other
    std::string text;     // as given, for messages and to compare units of kind Other
    bool sameKind(const AxisUnit& other) const {
        return kind == other.kind && (kind != UnitKind::Other || text == other.text);
    }
};

AxisUnit parseAxisUnit(const std::string& unit);

// The length of one degree of latitude on the WGS84 ellipsoid's mean, for maps whose vertical is in
// metres: close enough for a display proportion.
inline constexpr double kMetresPerDegreeOfLatitude = 111320.0;

}  // namespace tstyles
