// The sun's position from ERFA against the published test case of NREL's Solar Position
// Algorithm (Reda & Andreas 2004, "Solar position algorithm for solar radiation applications",
// Solar Energy 76, table A5.1), and local times through the tz database.
#include "aerial/astronomy/sun_date.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aerial/error.h"

namespace aerial::astronomy {
namespace {

// SPA's case: 2003-10-17 12:30:30 local at UTC-7 in Golden, Colorado, 1830.14 m up, 820 hPa and
// 11 C; SPA takes TT - UT1 = 67 s and UT1 = UTC, so dut1 = 0 here (ERFA's TT then differs from
// SPA's by 2.8 s, 0.1 arcsecond of the sun's motion along the ecliptic).
const SunDate kSpaDate{"2003-10-17", "12:30:30", "-07:00", 39.742476, -105.1786};
const Observer kSpaObserver{39.742476, -105.1786, 1830.14};
constexpr double kSpaZenithDeg = 50.11162, kSpaAzimuthDeg = 194.34024, kSpaDistanceAu = 0.9965422974;
// SPA states +-0.0003 degrees for its own angles over the years -2000 to 6000; ERFA's are
// finer (sub-arcsecond), so the difference must be within SPA's bound.
constexpr double kSpaAccuracyDeg = 0.0003;
// What the messages call SunDate's fields here.
const SunDateFields kFields{"date", "time", "time_zone", "latitude_deg", "longitude_deg"};

// SPA's refraction (its equation 42, Bennett's formula scaled for pressure and temperature), in
// degrees of elevation for the geometric elevation e0: to take it out of SPA's published zenith.
double SpaRefractionDeg(double e0_deg, double pressure_hpa, double temperature_c) {
  return pressure_hpa / 1010.0 * 283.0 / (273.0 + temperature_c) * 1.02 /
         (60.0 * std::tan((e0_deg + 10.3 / (e0_deg + 5.11)) * M_PI / 180.0));
}

TEST(SunPosition, MatchesTheSpaTestCaseWithinSpasAccuracy) {
  const UtcTime utc = ToUtc(kSpaDate, kFields, "");
  EXPECT_EQ(utc.hour, 19);
  EXPECT_EQ(utc.minute, 30);
  EXPECT_EQ(utc.second, 30.0);
  const SunPosition geometric = ComputeSunPosition(utc, kSpaObserver);
  // SPA's geometric zenith: its published (refracted) one with its own refraction taken out. The
  // refraction is a function of the geometric elevation, solved here by fixed-point iteration.
  double spa_geometric_zenith = kSpaZenithDeg;
  for (int i = 0; i < 5; ++i)
    spa_geometric_zenith = kSpaZenithDeg + SpaRefractionDeg(90.0 - spa_geometric_zenith, 820.0, 11.0);
  EXPECT_NEAR(geometric.zenith_deg, spa_geometric_zenith, kSpaAccuracyDeg);
  EXPECT_NEAR(geometric.azimuth_deg, kSpaAzimuthDeg, kSpaAccuracyDeg);
  EXPECT_NEAR(geometric.distance_au, kSpaDistanceAu, 1e-6);  // eraEpv00: 4.6 km, 3e-8 au

  // With ERFA's refraction: its model (A tan z + B tan^3 z from eraRefco) puts 56.1 arcseconds
  // at this elevation where SPA's formula puts 58.8, so the refracted zeniths differ by 0.00074
  // degrees; bounded at 0.001.
  const SunPosition refracted =
      ComputeSunPosition(utc, kSpaObserver, {.refraction = Refraction{.pressure_hpa = 820.0, .temperature_c = 11.0}});
  EXPECT_NEAR(refracted.zenith_deg, kSpaZenithDeg, 0.001);
  EXPECT_LT(refracted.zenith_deg, geometric.zenith_deg - 0.014);  // raised by about a minute of arc
  EXPECT_EQ(refracted.azimuth_deg, geometric.azimuth_deg);
  // The default place is sea level: the 1830 m of the case move the sun by far less than SPA's
  // accuracy (parallax of 8.8 arcseconds scaled by 1830 m / 6371 km).
  const Sun sun = SunFromDate(kSpaDate, kFields, "");
  EXPECT_NEAR(sun.zenith_deg, geometric.zenith_deg, 1e-5);
  EXPECT_NEAR(sun.azimuth_deg, geometric.azimuth_deg, 1e-5);
}

// A zone's offset follows its daylight-saving rules: Paris is UTC+2 in July and UTC+1 in January.
TEST(SunPosition, TimeZonesFollowTheTzDatabase) {
  auto hour = [](const std::string& date, const std::string& zone) {
    return ToUtc({date, "12:00", zone, 48.85, 2.35}, kFields, "").hour;
  };
  EXPECT_EQ(hour("2024-07-01", "Europe/Paris"), 10);
  EXPECT_EQ(hour("2024-01-15", "Europe/Paris"), 11);
  EXPECT_EQ(hour("2024-07-01", "+02:00"), 10);
  EXPECT_EQ(hour("2024-07-01", "UTC"), 12);
  EXPECT_EQ(hour("2024-07-01", "-0530"), 17);
  // The date changes with the offset: noon on 1 January in Kiribati (UTC+14) is 22:00 the day before.
  const UtcTime kiribati = ToUtc({"2024-01-01", "12:00", "Pacific/Kiritimati", 1.87, -157.4}, kFields, "");
  EXPECT_EQ(kiribati.year, 2023);
  EXPECT_EQ(kiribati.day, 31);
  EXPECT_EQ(kiribati.hour, 22);
}

// Each bad value is named with its field, whichever of the fields it is.
TEST(SunPosition, BadInputNamesTheFieldAndTheValue) {
  struct Case {
    SunDate date;
    std::string field, value;
  };
  const Case cases[] = {
      {{"2023-02-29", "12:00", "UTC", 0, 0}, "date", "2023-02-29"},
      {{"2023-13-01", "12:00", "UTC", 0, 0}, "date", "2023-13-01"},
      {{"17/10/2003", "12:00", "UTC", 0, 0}, "date", "17/10/2003"},
      {{"1959-12-31", "12:00", "UTC", 0, 0}, "date", "1959-12-31"},
      {{"2003-10-17", "24:00", "UTC", 0, 0}, "time", "24:00"},
      {{"2003-10-17", "noon", "UTC", 0, 0}, "time", "noon"},
      {{"2003-10-17", "12:00", "Europe/Pariss", 0, 0}, "time_zone", "Europe/Pariss"},
      {{"2003-10-17", "12:00", "+15:00", 0, 0}, "time_zone", "+15:00"},
      {{"2003-10-17", "12:00", "UTC", 90.5, 0}, "latitude_deg", "90.5"},
      {{"2003-10-17", "12:00", "UTC", NAN, 0}, "latitude_deg", "nan"},
      {{"2003-10-17", "12:00", "UTC", 0, -181}, "longitude_deg", "-181"},
      // The clocks go forward at 02:00 on 2024-03-31 in Paris, and back at 03:00 on 2024-10-27.
      {{"2024-03-31", "02:30", "Europe/Paris", 48.85, 2.35}, "time", "02:30"},
      {{"2024-10-27", "02:30", "Europe/Paris", 48.85, 2.35}, "time", "02:30"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.field + " = " + c.value);
    try {
      SunFromDate(c.date, kFields, "command line");
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), c.field);
      EXPECT_EQ(e.value(), c.value);
      EXPECT_EQ(e.where(), "command line");
    }
  }
}

}  // namespace
}  // namespace aerial::astronomy
