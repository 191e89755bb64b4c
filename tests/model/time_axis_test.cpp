// CF time units and calendars: known dates in each calendar (closed form; the Gregorian ones agree
// with Python's datetime), the labels, and the errors.
#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/data/time_axis.h"

namespace tstyles {
namespace {

TimeAxis axisOf(const std::string& units, const std::string& calendar = "") {
    return parseTimeUnits(units, calendar, "f.nc", "time");
}

CalendarDate date(int year, int month, int day, int hour = 0, int minute = 0) {
    return {year, month, day, hour, minute, 0.0};
}

TEST(TimeAxis, StandardCalendarDays) {
    // datetime.date(1900, 1, 1) + timedelta(days=40007) == date(2009, 7, 15)
    EXPECT_EQ(dateAt(axisOf("days since 1900-01-01"), 40007.0), date(2009, 7, 15));
    EXPECT_EQ(dateAt(axisOf("days since 1900-01-01", "gregorian"), 40007.0), date(2009, 7, 15));
}

TEST(TimeAxis, StandardCalendarJumpsFromJulianToGregorianIn1582) {
    EXPECT_EQ(dateAt(axisOf("days since 1582-10-04", "standard"), 1.0), date(1582, 10, 15));
    EXPECT_EQ(dateAt(axisOf("days since 1582-10-04", "proleptic_gregorian"), 1.0), date(1582, 10, 5));
    // 1500 is a leap year in the Julian calendar only.
    EXPECT_EQ(dateAt(axisOf("days since 1500-02-28", "standard"), 1.0), date(1500, 2, 29));
    EXPECT_EQ(dateAt(axisOf("days since 1500-02-28", "proleptic_gregorian"), 1.0), date(1500, 3, 1));
}

TEST(TimeAxis, JulianCalendar) {
    EXPECT_EQ(dateAt(axisOf("days since 1900-01-01", "julian"), 59.0), date(1900, 2, 29));
    EXPECT_EQ(dateAt(axisOf("days since 1900-01-01", "standard"), 59.0), date(1900, 3, 1));
}

TEST(TimeAxis, NoLeapAndAllLeapCalendars) {
    EXPECT_EQ(dateAt(axisOf("days since 2000-01-01", "noleap"), 59.0), date(2000, 3, 1));
    EXPECT_EQ(dateAt(axisOf("days since 2000-01-01", "365_day"), 365.0), date(2001, 1, 1));
    EXPECT_EQ(dateAt(axisOf("days since 1950-01-01", "noleap"), 21914.0), date(2010, 1, 15));
    EXPECT_EQ(dateAt(axisOf("days since 2001-01-01", "all_leap"), 59.0), date(2001, 2, 29));
    EXPECT_EQ(dateAt(axisOf("days since 2001-01-01", "366_day"), 366.0), date(2002, 1, 1));
}

TEST(TimeAxis, ThreeHundredSixtyDayCalendar) {
    EXPECT_EQ(dateAt(axisOf("days since 2000-01-01", "360_day"), 30.0), date(2000, 2, 1));
    EXPECT_EQ(dateAt(axisOf("days since 2000-01-01", "360_day"), 59.0), date(2000, 2, 30));
    EXPECT_EQ(dateAt(axisOf("days since 2000-01-01", "360_day"), 360.0), date(2001, 1, 1));
}

TEST(TimeAxis, HoursAndMinutesSinceADateAndTime) {
    EXPECT_EQ(dateAt(axisOf("hours since 2009-07-01T06:00:00Z"), 30.0), date(2009, 7, 2, 12, 0));
    EXPECT_EQ(dateAt(axisOf("minutes since 1950-1-1 00:00:0.0"), 90.0), date(1950, 1, 1, 1, 30));
    EXPECT_EQ(dateAt(axisOf("days since 2000-01-01"), 0.25), date(2000, 1, 1, 6, 0));
    EXPECT_EQ(dateAt(axisOf("seconds since 1970-01-01 00:00:00"), -1.0), (CalendarDate{1969, 12, 31, 23, 59, 59.0}));
}

using Labels = std::vector<std::string>;

// Monthly means stamped mid-month: 730.5-hour steps (a 365.25-day year over 12) from mid-January.
std::vector<double> monthlyHours(double first) {
    std::vector<double> hours;
    for (int month = 0; month < 12; ++month) hours.push_back(first + 730.5 * month);
    return hours;
}

TEST(TimeAxis, MonthlyDataIsLabelledByMonth) {
    EXPECT_EQ(formatTimes({0, 31, 59}, axisOf("days since 2009-01-15", "noleap")),
              (Labels{"2009-01", "2009-02", "2009-03"}));
    // Across a year's end, on the 360-day calendar.
    EXPECT_EQ(formatTimes({0, 30, 60}, axisOf("days since 2009-11-16", "360_day")),
              (Labels{"2009-11", "2009-12", "2010-01"}));
}

TEST(TimeAxis, AClimatologyIsLabelledByMonthName) {
    // Year 0 (the climatology read "0000-02-15 16:29:06" for its second month).
    const Labels names{"Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
    EXPECT_EQ(formatTimes(monthlyHours(366.0), axisOf("hours since 0000-01-01", "360_day")), names);
    // Year 1, and a dated climatology named so by its CF `climatology` attribute.
    EXPECT_EQ(formatTimes(monthlyHours(360.0), axisOf("hours since 0001-01-01 00:00:00", "noleap")), names);
    TimeAxis dated = axisOf("hours since 1981-01-01", "noleap");
    EXPECT_EQ(formatTimes(monthlyHours(360.0), dated)[1], "1981-02");
    dated.climatology = true;
    EXPECT_EQ(formatTimes(monthlyHours(360.0), dated), names);
    // Daily, in a climatology: month and day.
    EXPECT_EQ(formatTimes({45, 46}, axisOf("days since 0001-01-01", "noleap")), (Labels{"Feb 15", "Feb 16"}));
}

TEST(TimeAxis, MonthsSinceADateAreCalendarMonths) {
    // The World Ocean Atlas' monthly climatology: "months since 0000-01-01", stamps 0.5 .. 11.5 at
    // the middle of each month (noleap here, so the days are exact): 15.5 days into January (31
    // days), 14 into February (28), 15.5 into December (334 days after January 1st).
    const auto months =
        readCalendarMonths("months since 0000-01-01 00:00:00", "noleap", {0.5, 1.5, 11.5}, "woa.nc", "time");
    ASSERT_TRUE(months);
    EXPECT_EQ(months->axis, axisOf("days since 0000-01-01 00:00:00", "noleap"));
    EXPECT_EQ(months->days, (std::vector<double>{15.5, 45.0, 349.5}));
    TimeAxis climatology = months->axis;
    climatology.climatology = true;
    EXPECT_EQ(formatTimes(months->days, climatology), (Labels{"Jan", "Feb", "Dec"}));
    // Years: whole years, then months of the next (1.5 years after 2000-01-01 is 2001-07-01, 181
    // days into the noleap year).
    const auto years = readCalendarMonths("years since 2000-01-01", "noleap", {0.0, 1.5}, "f.nc", "time");
    ASSERT_TRUE(years);
    EXPECT_EQ(years->days, (std::vector<double>{0.0, 546.0}));
    // Other units are not months; a bad date is an error naming the field.
    EXPECT_FALSE(readCalendarMonths("days since 2000-01-01", "", {1.0}, "f.nc", "time"));
    EXPECT_FALSE(readCalendarMonths("months", "", {1.0}, "f.nc", "time"));
    EXPECT_THROW(readCalendarMonths("months since yesterday", "", {1.0}, "f.nc", "time"), InputError);
}

TEST(TimeAxis, YearlyAndDailyDataByYearAndDate) {
    EXPECT_EQ(formatTimes({0, 365, 730}, axisOf("days since 2000-07-01", "noleap")), (Labels{"2000", "2001", "2002"}));
    EXPECT_EQ(formatTimes({0, 1, 2}, axisOf("days since 2009-07-15")),
              (Labels{"2009-07-15", "2009-07-16", "2009-07-17"}));
    // Daily means stamped at noon need no time of day.
    EXPECT_EQ(formatTimes({0.5, 1.5}, axisOf("days since 2009-07-15")), (Labels{"2009-07-15", "2009-07-16"}));
    // Steps under a day: the time of day; seconds only where minutes do not tell them apart.
    EXPECT_EQ(formatTimes({100, 100.25}, axisOf("days since 2000-01-01")),
              (Labels{"2000-04-10 00:00", "2000-04-10 06:00"}));
    EXPECT_EQ(formatTimes({0, 30}, axisOf("seconds since 2000-01-01 00:00:00")),
              (Labels{"2000-01-01 00:00:00", "2000-01-01 00:00:30"}));
    // A single stamp: its whole date, and its time of day where it has one.
    EXPECT_EQ(formatTimes({0}, axisOf("days since 2009-07-15")), (Labels{"2009-07-15"}));
    EXPECT_EQ(formatTimes({0.25}, axisOf("days since 2009-07-15")), (Labels{"2009-07-15 06:00"}));
}

TEST(TimeAxis, AForecastIsLabelledByHoursSinceItsStart) {
    EXPECT_EQ(formatTimes({0, 6, 12, 48}, axisOf("hours since 2024-05-01 00:00:00")),
              (Labels{"+0 h", "+6 h", "+12 h", "+48 h"}));
    EXPECT_EQ(formatTimes({0, 90, 180}, axisOf("minutes since 2024-05-01 00:00:00")),
              (Labels{"+0 min", "+90 min", "+180 min"}));
    EXPECT_EQ(formatTimes({3, 4.5}, axisOf("hours since 2024-05-01 00:00:00")), (Labels{"+3 h", "+4.5 h"}));
    // Hours since a distant epoch are dates, not a forecast.
    EXPECT_EQ(formatTimes({960000, 960006}, axisOf("hours since 1900-01-01")),
              (Labels{"2009-07-08 00:00", "2009-07-08 06:00"}));
}

TEST(TimeAxis, DurationsInTheCoarsestWholeUnit) {
    EXPECT_EQ(formatTimes({0, 12.2, 24.4}, axisOf("s")), (Labels{"0 s", "12.2 s", "24.4 s"}));
    EXPECT_EQ(formatTimes({0, 60, 120}, axisOf("seconds")), (Labels{"0 min", "1 min", "2 min"}));
    EXPECT_EQ(formatTimes({0, 3600, 7200}, axisOf("seconds")), (Labels{"0 h", "1 h", "2 h"}));
    EXPECT_EQ(formatTimes({0, 2000, 4000}, axisOf("ms")), (Labels{"0 s", "2 s", "4 s"}));
    EXPECT_EQ(formatTimes({0, 24, 48}, axisOf("hours")), (Labels{"0 days", "1 day", "2 days"}));
    // Seconds stay seconds below a minute, and where minutes would not be whole.
    EXPECT_EQ(formatTimes({0, 90, 180}, axisOf("s")), (Labels{"0 s", "90 s", "180 s"}));
    EXPECT_EQ(formatTimes({1000.0, 1000.5}, axisOf("days")), (Labels{"1000 days", "1000.5 days"}));
    // Whole parts in full, never 1.5e+03.
    EXPECT_EQ(formatTimes({0, 1500, 3030}, axisOf("s")), (Labels{"0 s", "1500 s", "3030 s"}));
    EXPECT_EQ(formatTimes({0, 1500, 3000}, axisOf("s")), (Labels{"0 min", "25 min", "50 min"}));
    EXPECT_EQ(formatTimes({1500, 1501}, TimeAxis{}), (Labels{"1500", "1501"}));
    EXPECT_EQ(formatTimes({0, 1, 2}, TimeAxis{}), (Labels{"0", "1", "2"}));
}

TEST(TimeAxis, CfUnitsWrittenBack) {
    EXPECT_EQ(toCfUnits(axisOf("days since 1950-01-01", "noleap")), "days since 1950-01-01 00:00:00");
}

TEST(TimeAxis, WhatCannotBeReadIsAnInputError) {
    auto message = [](const std::string& units, const std::string& calendar) {
        try {
            axisOf(units, calendar);
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("days since 2000-01-01", "lunar").rfind("f.nc: time:calendar: unknown calendar \"lunar\"", 0), 0u);
    EXPECT_EQ(message("months since 2000-01-01", "").rfind("f.nc: time:units: \"months since 2000-01-01\": months", 0), 0u);
    EXPECT_EQ(message("fortnights", "").rfind("f.nc: time:units: \"fortnights\" is not a time unit", 0), 0u);
    EXPECT_EQ(message("days since yesterday", "").rfind("f.nc: time:units: \"days since yesterday\": cannot read", 0), 0u);
    EXPECT_NE(message("days since 2001-02-29", "noleap").find("does not exist in the noleap calendar"), std::string::npos);
    EXPECT_EQ(message("days since 2001-02-30", "360_day"), "no error");
}

}  // namespace
}  // namespace tstyles
