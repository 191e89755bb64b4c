// CF time units, calendars and labels (time_axis.h). Day numbers: Julian day numbers for the
// Gregorian and Julian calendars (the integer algorithms of Richards, "Mapping Time", as in the
// Explanatory Supplement to the Astronomical Almanac), plain counts for the fixed-length calendars.
#include "tstyles/core/ascii_case.h"
#include "tstyles/data/time_axis.h"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

constexpr long kFirstGregorianDay = 2299161;  // Julian day number of 1582-10-15 (Gregorian)
constexpr int kMonthDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};

long floorDivide(long a, long b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }

// Both day-number formulas count years from March of 4801 BC, so that February is the last month.
struct MarchYear {
    long year;
    long month;  // 0 for March .. 11 for February
};

MarchYear marchYear(int year, int month) {
    const long a = (14 - month) / 12;
    return {long(year) + 4800 - a, month + 12 * a - 3};
}

long gregorianDayNumber(int year, int month, int day) {
    const auto [y, m] = marchYear(year, month);
    return day + (153 * m + 2) / 5 + 365 * y + floorDivide(y, 4) - floorDivide(y, 100) + floorDivide(y, 400) - 32045;
}

long julianDayNumber(int year, int month, int day) {
    const auto [y, m] = marchYear(year, month);
    return day + (153 * m + 2) / 5 + 365 * y + floorDivide(y, 4) - 32083;
}

// Both inverses end alike: `days` into a run of Julian four-year cycles that starts in March,
// `centuries` hundred years after the era's start.
CalendarDate fromMarchCycles(long days, long centuries) {
    const long d = floorDivide(4 * days + 3, 1461);
    const long e = days - floorDivide(1461 * d, 4);
    const long m = floorDivide(5 * e + 2, 153);
    CalendarDate date;
    date.day = int(e - floorDivide(153 * m + 2, 5) + 1);
    date.month = int(m + 3 - 12 * floorDivide(m, 10));
    date.year = int(100 * centuries + d - 4800 + floorDivide(m, 10));
    return date;
}

CalendarDate fromGregorianDayNumber(long jdn) {
    const long a = jdn + 32044;
    const long b = floorDivide(4 * a + 3, 146097);
    return fromMarchCycles(a - floorDivide(146097 * b, 4), b);
}

CalendarDate fromJulianDayNumber(long jdn) { return fromMarchCycles(jdn + 32082, 0); }

int daysBeforeMonth(int month, bool leap) {
    int days = 0;
    for (int m = 1; m < month; ++m) days += kMonthDays[m - 1] + (leap && m == 2 ? 1 : 0);
    return days;
}

CalendarDate fromFixedYear(long dayNumber, int yearLength, bool leap) {
    CalendarDate date;
    date.year = int(floorDivide(dayNumber, yearLength));
    long dayOfYear = dayNumber - long(date.year) * yearLength;
    date.month = 1;
    while (true) {
        const int length = yearLength == 360 ? 30 : kMonthDays[date.month - 1] + (leap && date.month == 2 ? 1 : 0);
        if (dayOfYear < length || date.month == 12) break;
        dayOfYear -= length;
        ++date.month;
    }
    date.day = int(dayOfYear) + 1;
    return date;
}

long dayNumber(Calendar calendar, const CalendarDate& date) {
    switch (calendar) {
        case Calendar::Standard: {
            const long gregorian = gregorianDayNumber(date.year, date.month, date.day);
            return gregorian >= kFirstGregorianDay ? gregorian : julianDayNumber(date.year, date.month, date.day);
        }
        case Calendar::ProlepticGregorian: return gregorianDayNumber(date.year, date.month, date.day);
        case Calendar::Julian: return julianDayNumber(date.year, date.month, date.day);
        case Calendar::NoLeap: return 365L * date.year + daysBeforeMonth(date.month, false) + date.day - 1;
        case Calendar::AllLeap: return 366L * date.year + daysBeforeMonth(date.month, true) + date.day - 1;
        case Calendar::Day360: return 360L * date.year + 30L * (date.month - 1) + date.day - 1;
    }
    return 0;
}

CalendarDate fromDayNumber(Calendar calendar, long number) {
    switch (calendar) {
        case Calendar::Standard:
            return number >= kFirstGregorianDay ? fromGregorianDayNumber(number) : fromJulianDayNumber(number);
        case Calendar::ProlepticGregorian: return fromGregorianDayNumber(number);
        case Calendar::Julian: return fromJulianDayNumber(number);
        case Calendar::NoLeap: return fromFixedYear(number, 365, false);
        case Calendar::AllLeap: return fromFixedYear(number, 366, true);
        case Calendar::Day360: return fromFixedYear(number, 360, false);
    }
    return {};
}

int monthLength(Calendar calendar, int year, int month) {
    const long start = dayNumber(calendar, {year, month, 1});
    const long next = month == 12 ? dayNumber(calendar, {year + 1, 1, 1}) : dayNumber(calendar, {year, month + 1, 1});
    return int(next - start);
}

double secondsPer(TimeUnit unit) {
    switch (unit) {
        case TimeUnit::Microseconds: return 1e-6;
        case TimeUnit::Milliseconds: return 1e-3;
        case TimeUnit::Seconds: return 1.0;
        case TimeUnit::Minutes: return 60.0;
        case TimeUnit::Hours: return 3600.0;
        case TimeUnit::Days: return 86400.0;
        case TimeUnit::None: return 1.0;
    }
    return 1.0;
}

std::optional<TimeUnit> unitFromString(const std::string& text) {
    static const std::pair<const char*, TimeUnit> kNames[] = {
        {"days", TimeUnit::Days},       {"day", TimeUnit::Days},         {"d", TimeUnit::Days},
        {"hours", TimeUnit::Hours},     {"hour", TimeUnit::Hours},       {"hrs", TimeUnit::Hours},
        {"hr", TimeUnit::Hours},        {"h", TimeUnit::Hours},          {"minutes", TimeUnit::Minutes},
        {"minute", TimeUnit::Minutes},  {"mins", TimeUnit::Minutes},     {"min", TimeUnit::Minutes},
        {"seconds", TimeUnit::Seconds}, {"second", TimeUnit::Seconds},   {"secs", TimeUnit::Seconds},
        {"sec", TimeUnit::Seconds},     {"s", TimeUnit::Seconds},        {"milliseconds", TimeUnit::Milliseconds},
        {"millisecond", TimeUnit::Milliseconds}, {"msec", TimeUnit::Milliseconds}, {"ms", TimeUnit::Milliseconds},
        {"microseconds", TimeUnit::Microseconds}, {"microsecond", TimeUnit::Microseconds},
        {"usec", TimeUnit::Microseconds}, {"us", TimeUnit::Microseconds},
    };
    for (const auto& [name, unit] : kNames)
        if (text == name) return unit;
    return std::nullopt;
}

const char* unitSymbol(TimeUnit unit) {
    switch (unit) {
        case TimeUnit::Microseconds: return "us";
        case TimeUnit::Milliseconds: return "ms";
        case TimeUnit::Seconds: return "s";
        case TimeUnit::Minutes: return "min";
        case TimeUnit::Hours: return "h";
        case TimeUnit::Days: return "days";
        case TimeUnit::None: return "";
    }
    return "";
}

std::string trimmed(const std::string& text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::string twoDigits(int value) {
    char text[16];
    std::snprintf(text, sizeof text, "%02d", value);
    return text;
}

std::string dateText(const CalendarDate& date, int precision) {
    char text[64];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d", date.year, date.month, date.day);
    std::string result = text;
    if (precision >= 1) result += " " + twoDigits(date.hour) + ":" + twoDigits(date.minute);
    if (precision >= 2) result += ":" + twoDigits(int(std::floor(date.second)));
    return result;
}

std::string numberText(double value, int digits) {
    std::ostringstream text;
    text << std::setprecision(digits) << (value + 0.0);
    return text.str();
}

// Significant digits that print every value's whole part (1500, not 1.5e+03), and at least 3.
int leastDigits(const std::vector<double>& values) {
    double largest = 0.0;
    for (double value : values) largest = std::max(largest, std::abs(value));
    return largest < 1000.0 ? 3 : std::min(15, int(std::floor(std::log10(largest))) + 1);
}

bool allDistinct(const std::vector<std::string>& labels) {
    return std::set<std::string>(labels.begin(), labels.end()).size() == labels.size();
}

}  // namespace

std::string toString(Calendar calendar) {
    switch (calendar) {
        case Calendar::Standard: return "standard";
        case Calendar::ProlepticGregorian: return "proleptic_gregorian";
        case Calendar::NoLeap: return "noleap";
        case Calendar::AllLeap: return "all_leap";
        case Calendar::Day360: return "360_day";
        case Calendar::Julian: return "julian";
    }
    return "standard";
}

// A left-to-right reader of the reference date's few shapes.
class DateCursor {
public:
    explicit DateCursor(const std::string& text) : text_(text) {}
    bool atEnd() const { return at_ == text_.size(); }
    char peek(std::size_t ahead = 0) const { return at_ + ahead < text_.size() ? text_[at_ + ahead] : '\0'; }
    bool accept(char c) {
        if (peek() != c) return false;
        ++at_;
        return true;
    }
    bool accept(const char* word) {
        if (text_.compare(at_, std::string(word).size(), word) != 0) return false;
        at_ += std::string(word).size();
        return true;
    }
    // `least` to `most` digits (as many as there are); empty when fewer than `least`.
    std::string digits(std::size_t least, std::size_t most) {
        std::size_t end = at_;
        while (end < text_.size() && end - at_ < most && std::isdigit(static_cast<unsigned char>(text_[end]))) ++end;
        if (end - at_ < least) return "";
        std::string found = text_.substr(at_, end - at_);
        at_ = end;
        return found;
    }
    void skipSpaces() {
        while (std::isspace(static_cast<unsigned char>(peek()))) ++at_;
    }

private:
    const std::string& text_;
    std::size_t at_ = 0;
};

// [-]Y-M-D, optionally [ t]h[:m[:s[.fraction]]], then an optional zone of UTC (z, utc, +00:00).
std::optional<CalendarDate> parseReferenceDate(const std::string& text) {
    DateCursor cursor(text);
    CalendarDate date;
    const bool negative = cursor.accept('-');
    const std::string year = cursor.digits(1, 4);
    if (year.empty() || !cursor.accept('-')) return std::nullopt;
    const std::string month = cursor.digits(1, 2);
    if (month.empty() || !cursor.accept('-')) return std::nullopt;
    const std::string day = cursor.digits(1, 2);
    if (day.empty()) return std::nullopt;
    date.year = (negative ? -1 : 1) * std::stoi(year);
    date.month = std::stoi(month);
    date.day = std::stoi(day);
    if ((cursor.peek() == ' ' || cursor.peek() == 't') && std::isdigit(static_cast<unsigned char>(cursor.peek(1)))) {
        cursor.accept(cursor.peek());
        date.hour = std::stoi(cursor.digits(1, 2));
        if (cursor.peek() == ':' && std::isdigit(static_cast<unsigned char>(cursor.peek(1)))) {
            cursor.accept(':');
            date.minute = std::stoi(cursor.digits(1, 2));
            if (cursor.peek() == ':' && std::isdigit(static_cast<unsigned char>(cursor.peek(1)))) {
                cursor.accept(':');
                std::string second = cursor.digits(1, 2);
                if (cursor.accept('.')) second += "." + cursor.digits(0, 64);
                date.second = std::stod(second);
            }
        }
    }
    cursor.skipSpaces();
    if (!cursor.accept('z') && !cursor.accept("utc") && (cursor.accept('+') || cursor.accept('-'))) {
        const std::string hours = cursor.digits(1, 2);
        cursor.accept(':');
        const std::string minutes = cursor.digits(0, 2);
        if (hours.empty() || (hours + minutes).find_first_not_of('0') != std::string::npos) return std::nullopt;
    }
    return cursor.atEnd() ? std::optional<CalendarDate>(date) : std::nullopt;
}

std::optional<Calendar> calendarFromString(const std::string& name) {
    const std::string text = asciiLowercase(trimmed(name));
    if (text == "standard" || text == "gregorian" || text.empty()) return Calendar::Standard;
    if (text == "proleptic_gregorian") return Calendar::ProlepticGregorian;
    if (text == "noleap" || text == "365_day") return Calendar::NoLeap;
    if (text == "all_leap" || text == "366_day") return Calendar::AllLeap;
    if (text == "360_day") return Calendar::Day360;
    if (text == "julian") return Calendar::Julian;
    return std::nullopt;
}

TimeAxis parseTimeUnits(const std::string& units, const std::string& calendar, const std::filesystem::path& file,
                        const std::string& field) {
    TimeAxis axis;
    const auto parsedCalendar = calendarFromString(calendar);
    if (!parsedCalendar)
        throwInputError(file, field + ":calendar",
                        "unknown calendar \"" + calendar +
                            "\"; CF calendars: standard, gregorian, proleptic_gregorian, noleap, 365_day, all_leap, "
                            "366_day, 360_day, julian");
    axis.calendar = *parsedCalendar;
    const std::string text = asciiLowercase(trimmed(units));
    if (text.empty()) return axis;
    const auto since = text.find(" since ");
    const std::string unitText = trimmed(since == std::string::npos ? text : text.substr(0, since));
    if (unitText == "months" || unitText == "month" || unitText == "years" || unitText == "year")
        throwInputError(file, field + ":units",
                        "\"" + units + "\": months and years have no fixed length; CF asks for days, hours, minutes "
                        "or seconds");
    const auto unit = unitFromString(unitText);
    if (!unit)
        throwInputError(file, field + ":units", "\"" + units + "\" is not a time unit (days, hours, minutes, seconds, "
                                                "milliseconds, microseconds, optionally \"since\" a date)");
    axis.unit = *unit;
    if (since == std::string::npos) return axis;
    // 1950-01-01, 1950-1-1 00:00:00, 2009-07-01T06:00:00Z, 1950-01-01 00:00:0.0, 2000-01-01 0 (UDUNITS
    // takes an hour alone), with an optional zone of UTC.
    const std::string dateTextIn = trimmed(text.substr(since + 7));
    const auto parsed = parseReferenceDate(dateTextIn);
    if (!parsed)
        throwInputError(file, field + ":units", "\"" + units + "\": cannot read the reference date \"" + dateTextIn +
                                                    "\" (expected YYYY-MM-DD, optionally with hh:mm:ss)");
    const CalendarDate date = *parsed;
    const bool valid = date.month >= 1 && date.month <= 12 && date.day >= 1 &&
                       date.day <= monthLength(axis.calendar, date.year, date.month) && date.hour < 24 &&
                       date.minute < 60 && date.second < 61.0;
    if (!valid)
        throwInputError(file, field + ":units", "\"" + units + "\": the reference date " + dateTextIn + " does not exist in the " +
                                                    toString(axis.calendar) + " calendar");
    axis.reference = date;
    return axis;
}

std::optional<CalendarMonthStamps> readCalendarMonths(const std::string& units, const std::string& calendar,
                                                      const std::vector<double>& stamps,
                                                      const std::filesystem::path& file, const std::string& field) {
    const std::string text = asciiLowercase(trimmed(units));
    const auto since = text.find(" since ");
    if (since == std::string::npos) return std::nullopt;
    const std::string unitText = trimmed(text.substr(0, since));
    const bool years = unitText == "years" || unitText == "year";
    if (!years && unitText != "months" && unitText != "month") return std::nullopt;
    CalendarMonthStamps result;
    result.axis = parseTimeUnits("days" + text.substr(since), calendar, file, field);
    const CalendarDate reference = result.axis.reference.value();
    // The first of the month `months` after the reference's, at the reference's day (within the month) and time.
    const auto monthsAfter = [&](double months) {
        const double index = double(reference.year) * 12.0 + double(reference.month - 1) + months;
        CalendarDate date = reference;
        date.year = int(std::floor(index / 12.0));
        date.month = int(index - double(date.year) * 12.0) + 1;
        date.day = std::min(reference.day, monthLength(result.axis.calendar, date.year, date.month));
        return valueAt(result.axis, date, file, field);
    };
    for (double stamp : stamps) {
        const double months = years ? 12.0 * stamp : stamp;
        const double whole = std::floor(months);
        const double start = monthsAfter(whole);
        result.days.push_back(start + (months - whole) * (monthsAfter(whole + 1.0) - start));
    }
    return result;
}

std::string toCfUnits(const TimeAxis& axis) {
    if (axis.unit == TimeUnit::None) return "";
    static const char* kCfNames[] = {"", "microseconds", "milliseconds", "seconds", "minutes", "hours", "days"};
    std::string text = kCfNames[static_cast<int>(axis.unit)];
    if (!axis.reference) return text;
    const CalendarDate& date = *axis.reference;
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, " since %04d-%02d-%02d %02d:%02d:%02d", date.year, date.month, date.day,
                  date.hour, date.minute, int(date.second));
    return text + buffer;
}

CalendarDate dateAt(const TimeAxis& axis, double value) {
    const CalendarDate& reference = axis.reference.value();
    const double referenceSeconds = reference.hour * 3600.0 + reference.minute * 60.0 + reference.second;
    // Whole days and the second of the day, rounded to a millisecond so that 0.25 days is 06:00.
    const double seconds = std::round((referenceSeconds + value * secondsPer(axis.unit)) * 1000.0) / 1000.0;
    const double days = std::floor(seconds / 86400.0);
    double secondOfDay = seconds - days * 86400.0;
    CalendarDate date = fromDayNumber(axis.calendar, dayNumber(axis.calendar, reference) + long(days));
    date.hour = int(secondOfDay / 3600.0);
    secondOfDay -= date.hour * 3600.0;
    date.minute = int(secondOfDay / 60.0);
    date.second = secondOfDay - date.minute * 60.0;
    return date;
}

double valueAt(const TimeAxis& axis, const CalendarDate& date, const std::filesystem::path& source,
               const std::string& field) {
    const bool exists = date.month >= 1 && date.month <= 12 && date.day >= 1 &&
                        date.day <= monthLength(axis.calendar, date.year, date.month);
    if (!exists) {
        char text[32];
        std::snprintf(text, sizeof text, "%04d-%02d-%02d", date.year, date.month, date.day);
        throwInputError(source, field, std::string("the date ") + text + " does not exist in the " +
                                           toString(axis.calendar) + " calendar");
    }
    const CalendarDate& reference = axis.reference.value();
    const double days = double(dayNumber(axis.calendar, date) - dayNumber(axis.calendar, reference));
    const double seconds = (date.hour - reference.hour) * 3600.0 + (date.minute - reference.minute) * 60.0 +
                           (date.second - reference.second);
    return (days * 86400.0 + seconds) / secondsPer(axis.unit);
}

namespace {

constexpr const char* kMonthNames[12] = {"Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                         "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
constexpr double kSecondsPerDay = 86400.0;

// The smallest gap between neighbouring stamps, in seconds; infinity for fewer than two stamps.
double smallestStepSeconds(const std::vector<double>& values, const TimeAxis& axis) {
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 1; i < values.size(); ++i)
        smallest = std::min(smallest, std::abs(values[i] - values[i - 1]) * secondsPer(axis.unit));
    return smallest;
}

bool isClimatology(const std::vector<CalendarDate>& dates, const TimeAxis& axis) {
    if (axis.climatology) return true;
    for (const CalendarDate& date : dates)
        if (date.year != 0 && date.year != 1) return false;
    return true;
}

std::string yearText(const CalendarDate& date) {
    char text[16];
    std::snprintf(text, sizeof text, "%04d", date.year);
    return text;
}

std::string monthText(const CalendarDate& date, bool climatology) {
    if (climatology) return kMonthNames[date.month - 1];
    return yearText(date) + "-" + twoDigits(date.month);
}

std::string dayText(const CalendarDate& date, bool climatology) {
    if (climatology) return std::string(kMonthNames[date.month - 1]) + " " + std::to_string(date.day);
    return dateText(date, 0);
}

// Calendar labels at the coarsest unit whose labels tell the steps apart and whose unit the steps are
// at least as far apart as: years ("2009"), months ("2009-07", or "Jul" in a climatology), days
// ("2009-07-15", "Jul 15"), then the time of day ("2009-07-15 06:00") and seconds only where needed.
std::vector<std::string> calendarLabels(const std::vector<double>& values, const TimeAxis& axis) {
    std::vector<CalendarDate> dates;
    for (double value : values) dates.push_back(dateAt(axis, value));
    const bool climatology = isClimatology(dates, axis);
    const double step = smallestStepSeconds(values, axis);
    std::vector<std::string> labels(dates.size());
    auto tryLabels = [&](auto&& text) {
        for (std::size_t i = 0; i < dates.size(); ++i) labels[i] = text(dates[i]);
        return allDistinct(labels);
    };
    // 359 and 27 days: the shortest year and month of the CF calendars less a day, for stamps that
    // wander within their period (monthly means stamped mid-month). A single stamp has nothing to be
    // told apart from: its whole date, and its time of day where it has one.
    const bool several = dates.size() > 1;
    if (several && !climatology && step >= 359 * kSecondsPerDay && tryLabels(yearText)) return labels;
    if (several && step >= 27 * kSecondsPerDay &&
        tryLabels([&](const CalendarDate& d) { return monthText(d, climatology); }))
        return labels;
    if (several && step >= kSecondsPerDay && tryLabels([&](const CalendarDate& d) { return dayText(d, climatology); }))
        return labels;
    bool timeOfDay = several;
    for (const CalendarDate& date : dates) timeOfDay = timeOfDay || date.hour != 0 || date.minute != 0;
    for (int precision = timeOfDay ? 1 : 0; precision <= 2; ++precision)
        if (tryLabels([&](const CalendarDate& d) { return dateText(d, precision); })) break;
    return labels;
}

// A forecast: hours or minutes since the run's start, the first step within a day of it and the
// last within 16 days (the longest range of the operational global models). Labelled as offsets.
bool isForecast(const std::vector<double>& values, const TimeAxis& axis) {
    if (axis.unit != TimeUnit::Hours && axis.unit != TimeUnit::Minutes) return false;
    if (values.size() < 2 || values.front() < 0.0 || values.front() * secondsPer(axis.unit) > kSecondsPerDay)
        return false;
    for (double value : values)
        if (value < 0.0 || value * secondsPer(axis.unit) > 16 * kSecondsPerDay) return false;
    return true;
}

bool allWholeIn(const std::vector<double>& seconds, double unitSeconds) {
    for (double value : seconds) {
        const double inUnit = value / unitSeconds;
        if (std::abs(inUnit - std::round(inUnit)) > 1e-6 * std::max(1.0, std::abs(inUnit))) return false;
    }
    return true;
}

std::string durationText(double value, int digits, TimeUnit unit) {
    std::string text = numberText(value, digits) + " ";
    if (unit == TimeUnit::Days) return text + (value == 1.0 ? "day" : "days");
    return text + unitSymbol(unit);
}

// Durations in the file's unit, or in a coarser one up to `coarsest` where every stamp is a whole
// number of it and the steps are at least one apart (60 s steps read "1 min", "2 min"; 2 s steps
// stay seconds).
std::vector<std::string> durationLabels(const std::vector<double>& values, const TimeAxis& axis, TimeUnit coarsest,
                                        const std::string& prefix) {
    std::vector<double> seconds;
    for (double value : values) seconds.push_back(value * secondsPer(axis.unit));
    const double step = smallestStepSeconds(values, axis);
    TimeUnit unit = axis.unit;
    constexpr TimeUnit kCoarser[] = {TimeUnit::Milliseconds, TimeUnit::Seconds, TimeUnit::Minutes, TimeUnit::Hours,
                                     TimeUnit::Days};
    for (TimeUnit coarser : kCoarser)
        if (values.size() > 1 && secondsPer(coarser) > secondsPer(unit) &&
            secondsPer(coarser) <= secondsPer(coarsest) && step >= secondsPer(coarser) && allWholeIn(seconds, secondsPer(coarser)))
            unit = coarser;
    std::vector<double> inUnit;
    for (double value : seconds) inUnit.push_back(value / secondsPer(unit) + 0.0);
    std::vector<std::string> labels(values.size());
    for (int digits = leastDigits(inUnit); digits <= 15; ++digits) {
        for (std::size_t i = 0; i < values.size(); ++i) labels[i] = prefix + durationText(inUnit[i], digits, unit);
        if (allDistinct(labels)) break;
    }
    return labels;
}

}  // namespace

std::vector<std::string> formatTimes(const std::vector<double>& values, const TimeAxis& axis) {
    // Forecasts count in hours ("+48 h"), as forecasters do.
    if (axis.reference)
        return isForecast(values, axis) ? durationLabels(values, axis, TimeUnit::Hours, "+")
                                        : calendarLabels(values, axis);
    if (axis.unit != TimeUnit::None) return durationLabels(values, axis, TimeUnit::Days, "");
    std::vector<std::string> labels(values.size());
    for (int digits = leastDigits(values); digits <= 15; ++digits) {
        for (std::size_t i = 0; i < values.size(); ++i) labels[i] = numberText(values[i], digits);
        if (allDistinct(labels)) break;
    }
    return labels;
}

std::string formatTime(double value, const TimeAxis& axis) { return formatTimes({value}, axis).front(); }

}  // namespace tstyles
