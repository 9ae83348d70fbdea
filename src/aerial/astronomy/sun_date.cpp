#include "aerial/astronomy/sun_date.h"

#include <cmath>
#include <exception>
#include <regex>

#include <date/tz.h>

#include "aerial/core/format_number.h"
#include "aerial/error.h"

namespace aerial::astronomy {
namespace {

// The offset of the zone at a local time, in seconds east of UTC.
std::chrono::seconds ZoneOffset(const SunDate& given, const SunDateFields& fields, const std::string& where,
                                date::local_seconds local) {
  static const std::regex offset_form(R"((?:UTC|GMT)?([+-])(\d{1,2})(?::?(\d{2}))?)");
  std::smatch match;
  if (std::regex_match(given.time_zone, match, offset_form)) {
    int hours = std::stoi(match[2]), minutes = match[3].matched ? std::stoi(match[3]) : 0;
    // Real offsets run from -12:00 to +14:00.
    if (hours > 14 || minutes > 59 || hours * 60 + minutes > 14 * 60)
      throw Error(fields.time_zone, given.time_zone, "a UTC offset from -14:00 to +14:00", where);
    return std::chrono::seconds((match[1] == "-" ? -1 : 1) * (hours * 3600 + minutes * 60));
  }
  const date::time_zone* zone = nullptr;
  try {
    zone = date::locate_zone(given.time_zone);
  } catch (const std::exception&) {
    throw Error(fields.time_zone, given.time_zone,
                "a time zone of the tz database (Europe/Paris, America/Denver, UTC) or a UTC offset (+02:00, "
                "-07)",
                where);
  }
  const date::local_info info = zone->get_info(local);
  if (info.result == date::local_info::unique) return info.first.offset;
  const bool skipped = info.result == date::local_info::nonexistent;
  throw Error(fields.time, given.time,
              std::string("a clock time that ") + given.time_zone + " shows once on " + given.date +
                  (skipped ? " (it skips this one: the clocks go forward)" : " (it shows this one twice: the clocks go back)") +
                  "; a UTC offset as " + fields.time_zone + " says which is meant",
              where);
}

}  // namespace

UtcTime ToUtc(const SunDate& given, const SunDateFields& fields, const std::string& where) {
  static const std::regex date_form(R"((\d{4})-(\d{2})-(\d{2}))");
  static const std::regex time_form(R"((\d{1,2}):(\d{2})(?::(\d{2}(?:\.\d{1,9})?))?)");
  std::smatch match;
  const std::string date_allowed = "a date that exists, YYYY-MM-DD, from " + std::to_string(kFirstYear) +
                                   "-01-01 to " + std::to_string(kLastYear) + "-12-31";
  if (!std::regex_match(given.date, match, date_form)) throw Error(fields.date, given.date, date_allowed, where);
  const date::year_month_day day{date::year(std::stoi(match[1])), date::month(unsigned(std::stoi(match[2]))),
                                 date::day(unsigned(std::stoi(match[3])))};
  if (!day.ok() || int(day.year()) < kFirstYear || int(day.year()) > kLastYear)
    throw Error(fields.date, given.date, date_allowed, where);

  const std::string time_allowed = "a clock time HH:MM or HH:MM:SS, from 00:00 to 23:59:59";
  if (!std::regex_match(given.time, match, time_form)) throw Error(fields.time, given.time, time_allowed, where);
  const int hour = std::stoi(match[1]), minute = std::stoi(match[2]);
  const double second = match[3].matched ? std::stod(match[3]) : 0.0;
  if (hour > 23 || minute > 59 || second >= 60.0) throw Error(fields.time, given.time, time_allowed, where);

  if (!(given.latitude_deg >= -90.0 && given.latitude_deg <= 90.0))
    throw Error(fields.latitude, FormatNumber(given.latitude_deg), "a latitude in [-90, 90] degrees (north positive)",
                where);
  if (!(given.longitude_deg >= -180.0 && given.longitude_deg <= 180.0))
    throw Error(fields.longitude, FormatNumber(given.longitude_deg),
                "a longitude in [-180, 180] degrees (east positive)", where);

  const double whole_seconds = std::floor(second);
  const date::local_seconds local = date::local_days(day) + std::chrono::hours(hour) + std::chrono::minutes(minute) +
                                    std::chrono::seconds(int(whole_seconds));
  const date::sys_seconds instant{(local - ZoneOffset(given, fields, where, local)).time_since_epoch()};
  const date::sys_days utc_day = date::floor<date::days>(instant);
  const date::year_month_day utc_date(utc_day);
  const date::hh_mm_ss<std::chrono::seconds> clock(instant - utc_day);
  return {int(utc_date.year()), int(unsigned(utc_date.month())), int(unsigned(utc_date.day())),
          int(clock.hours().count()), int(clock.minutes().count()),
          double(clock.seconds().count()) + (second - whole_seconds)};
}

Sun SunFromDate(const SunDate& given, const SunDateFields& fields, const std::string& where) {
  const SunPosition sun = ComputeSunPosition(ToUtc(given, fields, where), {given.latitude_deg, given.longitude_deg, 0.0});
  return {.zenith_deg = sun.zenith_deg, .azimuth_deg = sun.azimuth_deg};
}

}  // namespace aerial::astronomy
