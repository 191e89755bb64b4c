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

TEST(TimeAxis, LabelsAreAsShortAsKeepsNeighboursApart) {
    EXPECT_EQ(formatTimes({0, 31, 59}, axisOf("days since 2009-01-15", "noleap")),
              (std::vector<std::string>{"2009-01-15", "2009-02-15", "2009-03-15"}));
    EXPECT_EQ(formatTimes({0, 6, 12}, axisOf("hours since 2000-01-01")),
              (std::vector<std::string>{"2000-01-01 00:00", "2000-01-01 06:00", "2000-01-01 12:00"}));
    EXPECT_EQ(formatTimes({0, 12.2, 24.4}, axisOf("s")), (std::vector<std::string>{"0 s", "12.2 s", "24.4 s"}));
    EXPECT_EQ(formatTimes({1000.0, 1000.5}, axisOf("days")), (std::vector<std::string>{"1000 days", "1000.5 days"}));
    EXPECT_EQ(formatTimes({0, 1, 2}, TimeAxis{}), (std::vector<std::string>{"0", "1", "2"}));
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
