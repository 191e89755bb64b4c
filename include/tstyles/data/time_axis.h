// What the time stamps of a series mean: a unit, and where the file gives one, a reference date on
// a calendar (CF "days since 1950-01-01", calendar "noleap"). Turns stamps into text a person reads
// ("2009-07-15", "12.2 s") for `tstyles info`, the viewer's time slider and the TSTF sections. GL-free.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tstyles {

// The CF calendars. Standard (= gregorian) is Julian before 1582-10-15 and Gregorian from then.
enum class Calendar { Standard, ProlepticGregorian, NoLeap, AllLeap, Day360, Julian };

std::string toString(Calendar calendar);  // the CF name: "standard", "noleap", "360_day", ...
// Every CF spelling, lower case ("gregorian", "365_day", "none" is not a calendar).
std::optional<Calendar> calendarFromString(const std::string& name);

struct CalendarDate {
    int year = 1970;
    int month = 1;  // 1 .. 12
    int day = 1;    // 1 .. the month's length in the calendar
    int hour = 0;
    int minute = 0;
    double second = 0.0;
    bool operator==(const CalendarDate&) const = default;
};

enum class TimeUnit { None, Microseconds, Milliseconds, Seconds, Minutes, Hours, Days };

struct TimeAxis {
    TimeUnit unit = TimeUnit::None;  // None: plain numbers (time-step indices, an unknown unit)
    std::optional<CalendarDate> reference;  // "<unit> since <reference>"
    Calendar calendar = Calendar::Standard;
    // The stamps stand for the same period of every year of a range (a CF time variable with a
    // `climatology` attribute): labels name months and days without a year ("Feb", "Feb 15").
    bool climatology = false;
    bool operator==(const TimeAxis&) const = default;
};

// CF units such as "days since 1950-01-01", "hours since 2009-07-01T06:00:00Z", "seconds"; an
// empty text is TimeUnit::None. What cannot be read (an unknown unit, a bad date, months or years,
// which CF discourages because their length varies, an unknown calendar) is an InputError naming
// `file` and `field`.
TimeAxis parseTimeUnits(const std::string& units, const std::string& calendar, const std::filesystem::path& file,
                        const std::string& field);

// CF's "months since DATE" and "years since DATE" read as calendar months and years, as the World
// Ocean Atlas and other climatologies use them (CF's own month, a twelfth of a tropical year, is
// what parseTimeUnits refuses): the stamps become days since DATE on the calendar, each one's whole
// months after DATE (DATE's day kept, within the month) plus its fraction of the next month's days,
// so 0.5 "months since 0000-01-01" is 0000-01-16 12:00. None for other units; an InputError naming
// `file` and `field` for a DATE or calendar that cannot be read.
struct CalendarMonthStamps {
    TimeAxis axis;             // "days since DATE"
    std::vector<double> days;  // the stamps, in days since DATE
};
std::optional<CalendarMonthStamps> readCalendarMonths(const std::string& units, const std::string& calendar,
                                                      const std::vector<double>& stamps,
                                                      const std::filesystem::path& file, const std::string& field);

// The CF spelling back ("days since 1950-01-01 00:00:00"); empty for TimeUnit::None.
std::string toCfUnits(const TimeAxis& axis);

// The date `value` units after the reference (the axis must have one).
CalendarDate dateAt(const TimeAxis& axis, double value);

// The inverse of dateAt: how many units after the reference `date` is on the axis' calendar (the
// axis must have a reference). An InputError naming `source` and `field` when the date does not
// exist in that calendar (February 30 outside 360_day).
double valueAt(const TimeAxis& axis, const CalendarDate& date, const std::filesystem::path& source,
               const std::string& field);

// Labels for a series' stamps in the coarsest unit that tells them apart and that the steps are at
// least one of: on a calendar, years ("2009"), months ("2009-07"; "Feb" in a climatology, which
// year 0 or 1 or the climatology flag makes one), days ("2009-07-15"), then "06:00" and seconds only
// where needed; a forecast (hours or minutes since a reference within a day of the first step, the
// last within 16 days) as offsets ("+6 h"); without a calendar, durations in the file's unit or a
// coarser one every stamp is a whole number of ("12.2 s", "2 min", "3 days"); plain numbers without
// a unit. docs/automatic-scene.md, "Time labels".
std::vector<std::string> formatTimes(const std::vector<double>& values, const TimeAxis& axis);
std::string formatTime(double value, const TimeAxis& axis);

}  // namespace tstyles
