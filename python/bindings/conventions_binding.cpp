// Time stamps and CF axes for the Python side's xarray conversion (python/tstyles/xarray_series.py),
// through the same code the NetCDF reader uses.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "tstyles/core/errors.h"
#include "tstyles/data/cf_conventions.h"
#include "tstyles/data/time_axis.h"

namespace py = pybind11;

namespace tstyles::python {
namespace {

using DateFields = std::tuple<int, int, int, int, int, double>;  // year, month, day, hour, minute, second

// Dates (datetime64 or cftime stamps, taken apart by the caller) as values on a CF time axis.
std::vector<double> timeValues(const std::string& units, const std::string& calendar,
                               const std::vector<DateFields>& dates, const std::string& source,
                               const std::string& field) {
    const TimeAxis axis = parseTimeUnits(units, calendar, source, field);
    if (!axis.reference) throwInputError(source, field + ":units", "\"" + units + "\" names no reference date");
    std::vector<double> values;
    for (const auto& [year, month, day, hour, minute, second] : dates)
        values.push_back(valueAt(axis, {year, month, day, hour, minute, second}, source, field));
    return values;
}

std::vector<DateFields> datesOf(const std::string& units, const std::string& calendar,
                                const std::vector<double>& values) {
    const TimeAxis axis = parseTimeUnits(units, calendar, "", "time");
    std::vector<DateFields> dates;
    if (!axis.reference) return dates;
    for (double value : values) {
        const CalendarDate date = dateAt(axis, value);
        dates.emplace_back(date.year, date.month, date.day, date.hour, date.minute, date.second);
    }
    return dates;
}

bool looksLikeTime(const std::string& dimension, const std::optional<py::dict>& attributes) {
    if (!attributes) return cfLooksLikeTime(dimension, nullptr);
    auto text = [&](const char* key) {
        return attributes->contains(key) ? py::str((*attributes)[key]).cast<std::string>() : std::string();
    };
    const CfAttributes cf{text("units"), text("standard_name"), text("axis"), text("positive")};
    return cfLooksLikeTime(dimension, &cf);
}

}  // namespace

void bindConventions(py::module_& module) {
    module.def("time_values", &timeValues);
    module.def("dates", &datesOf);
    module.def("looks_like_time", &looksLikeTime);
}

}  // namespace tstyles::python
