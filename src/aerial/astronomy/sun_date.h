#pragma once
// The sun from a local date, clock time and place, as a scene file's [sun] keys or the command
// line's options give them. Time zones come
// from the system's tz database (/usr/share/zoneinfo, Debian's tzdata) through Howard Hinnant's
// date library (the basis of C++20's <chrono> time zones), or are fixed UTC offsets.
#include <string>

#include "aerial/astronomy/sun_position.h"
#include "aerial/scene.h"

namespace aerial::astronomy {

struct SunDate {
  std::string date;       // YYYY-MM-DD, the local calendar date
  std::string time;       // HH:MM or HH:MM:SS[.fraction], the local clock
  std::string time_zone;  // an IANA name ("Europe/Paris", "UTC") or an offset ("+02:00", "-07", "+0530")
  double latitude_deg = 0.0;   // geodetic, north positive
  double longitude_deg = 0.0;  // east positive
};

// What messages call SunDate's fields: a scene file's keys, or a command line's options.
struct SunDateFields {
  std::string date, time, time_zone, latitude, longitude;
};

// The first and last years taken: UTC's leap-second table (ERFA's eraDat) starts in 1960, and the
// Earth's orbit (eraEpv00) holds its stated accuracy to 2100.
inline constexpr int kFirstYear = 1960, kLastYear = 2100;

// The UTC instant of the local date and time. Throws aerial::Error(field, value, allowed, where)
// for a malformed or non-existent date (2023-02-29), a year outside [kFirstYear, kLastYear], a
// malformed clock time, an unknown zone, a local time the zone skips or repeats (a daylight-saving
// change: an offset says which), or a latitude outside [-90, 90] or longitude outside [-180, 180].
UtcTime ToUtc(const SunDate& date, const SunDateFields& fields, const std::string& where);

// The geometric sun (sun_position.h) at that instant, seen from that place at sea level, as the
// scene's sun (compass azimuth from north, as scene.h's). Throws as ToUtc.
Sun SunFromDate(const SunDate& date, const SunDateFields& fields, const std::string& where);

}  // namespace aerial::astronomy
