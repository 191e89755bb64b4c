// Axis units to kinds and factors (axis_units.h).
#include "axis_units.h"

#include <algorithm>
#include <cctype>
#include <numbers>
#include <utility>

#include "tstyles/core/ascii_case.h"

namespace tstyles {
namespace {

// Without spaces, in lower case: "Degrees North" -> "degreesnorth".
std::string normalised(const std::string& unit) {
    std::string text;
    for (char c : unit)
        if (!std::isspace(static_cast<unsigned char>(c))) text += c;
    return asciiLowercase(text);
}

struct KnownUnit {
    const char* name;
    UnitKind kind;
    double toBase;
};

// Lower case; CF (UDUNITS) spellings, NIfTI's and NRRD's. Degrees of longitude and latitude
// (degrees_east, degree_n, ...) are angles like plain degrees.
constexpr KnownUnit kKnownUnits[] = {
    {"m", UnitKind::Length, 1.0},          {"meter", UnitKind::Length, 1.0},
    {"meters", UnitKind::Length, 1.0},     {"metre", UnitKind::Length, 1.0},
    {"metres", UnitKind::Length, 1.0},     {"km", UnitKind::Length, 1e3},
    {"kilometer", UnitKind::Length, 1e3},  {"kilometers", UnitKind::Length, 1e3},
    {"kilometre", UnitKind::Length, 1e3},  {"kilometres", UnitKind::Length, 1e3},
    {"cm", UnitKind::Length, 1e-2},        {"mm", UnitKind::Length, 1e-3},
    {"millimeter", UnitKind::Length, 1e-3}, {"millimeters", UnitKind::Length, 1e-3},
    {"millimetre", UnitKind::Length, 1e-3}, {"millimetres", UnitKind::Length, 1e-3},
    {"um", UnitKind::Length, 1e-6},        {"micron", UnitKind::Length, 1e-6},
    {"microns", UnitKind::Length, 1e-6},   {"µm", UnitKind::Length, 1e-6},
    {"nm", UnitKind::Length, 1e-9},        {"ft", UnitKind::Length, 0.3048},
    {"feet", UnitKind::Length, 0.3048},    {"foot", UnitKind::Length, 0.3048},
    {"pa", UnitKind::Pressure, 1.0},       {"hpa", UnitKind::Pressure, 100.0},
    {"kpa", UnitKind::Pressure, 1e3},      {"mbar", UnitKind::Pressure, 100.0},
    {"millibar", UnitKind::Pressure, 100.0}, {"millibars", UnitKind::Pressure, 100.0},
    {"mb", UnitKind::Pressure, 100.0},     {"dbar", UnitKind::Pressure, 1e4},
    {"decibar", UnitKind::Pressure, 1e4},  {"bar", UnitKind::Pressure, 1e5},
    {"atm", UnitKind::Pressure, 101325.0},
    {"rad", UnitKind::Angle, 180.0 / std::numbers::pi}, {"radians", UnitKind::Angle, 180.0 / std::numbers::pi},
};

bool isDegrees(const std::string& text) {
    // degree, degrees, deg, degree_east, degrees_north, degree_e, degreesn, ...
    for (const char* stem : {"degrees", "degree", "deg"}) {
        const std::string prefix = stem;
        if (text.rfind(prefix, 0) != 0) continue;
        std::string rest = text.substr(prefix.size());
        if (!rest.empty() && rest.front() == '_') rest.erase(0, 1);
        return rest.empty() || rest == "e" || rest == "n" || rest == "w" || rest == "s" || rest == "east" ||
               rest == "north" || rest == "west" || rest == "south" || rest == "true";
    }
    return false;
}

}  // namespace

AxisUnit parseAxisUnit(const std::string& unit) {
    const std::string text = normalised(unit);
    if (text.empty()) return {UnitKind::None, 1.0, unit};
    if (isDegrees(text)) return {UnitKind::Angle, 1.0, unit};
    for (const KnownUnit& known : kKnownUnits)
        if (text == known.name) return {known.kind, known.toBase, unit};
    return {UnitKind::Other, 1.0, unit};
}

}  // namespace tstyles
