// The sun of a date and a place in scene files ([sun] date, time, time_zone, latitude_deg,
// longitude_deg): the same sun as the astronomy module's, never together with the angles, every
// bad key named.
#include "aerial/scene/sun_date_keys.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "aerial/astronomy/sun_date.h"
#include "aerial/error.h"
#include "aerial/scene/scene_file.h"

namespace aerial {
namespace {

constexpr double kR = 6360e3;
const astronomy::SunDate kGolden{"2003-10-17", "12:30:30", "-07:00", 39.742476, -105.1786};
const astronomy::SunDateFields kFields{"date", "time", "time_zone", "latitude_deg", "longitude_deg"};

Scene Parse(const std::string& sun_table) {
  return ParseSceneToml("built_in = false\n[sun]\n" + sun_table, "test.toml", ".", kR);
}

void ExpectError(const std::string& sun_table, const std::string& field, const std::string& value) {
  try {
    Parse(sun_table);
    ADD_FAILURE() << "accepted:\n" << sun_table;
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_EQ(e.value(), value) << e.what();
    EXPECT_EQ(e.where().rfind("test.toml:", 0), 0u) << e.what();
  }
}

TEST(SunDateInScenes, TomlDatesTimesAndStringsGiveTheAstronomySun) {
  const Sun expected = astronomy::SunFromDate(kGolden, kFields, "");
  const char* places = "time_zone = \"-07:00\"\nlatitude_deg = 39.742476\nlongitude_deg = -105.1786\n";
  for (const std::string& when : {std::string("date = 2003-10-17\ntime = 12:30:30\n"),
                                  std::string("date = \"2003-10-17\"\ntime = \"12:30:30\"\n")}) {
    const Scene scene = Parse(when + places);
    EXPECT_EQ(scene.sun.zenith_deg, expected.zenith_deg);
    EXPECT_EQ(scene.sun.azimuth_deg, expected.azimuth_deg);
  }
  // The sun of the case is 50 degrees from the zenith, in the south-southwest (SPA's 194.34).
  EXPECT_NEAR(expected.zenith_deg, 50.128, 0.001);
  EXPECT_NEAR(expected.azimuth_deg, 194.340, 0.001);
}

// examples/scenes/dated.toml is the SPA case above.
TEST(SunDateInScenes, TheExampleSceneHasTheSpaSun) {
  const Scene scene = LoadSceneFile(std::filesystem::path(AERIAL_SOURCE_DIR) / "examples/scenes/dated.toml", kR);
  EXPECT_EQ(scene.sun, astronomy::SunFromDate(kGolden, kFields, ""));
}

TEST(SunDateInScenes, BadKeysAreNamedWithTheirFile) {
  const std::string place = "latitude_deg = 39.7\nlongitude_deg = -105.2\n";
  ExpectError("date = 2003-10-17\ntime = 12:30:30\n" + place, "sun.time_zone", "(not given)");
  ExpectError("date = 2003-10-17\ntime = 12:30:30\ntime_zone = \"Mountain\"\n" + place, "sun.time_zone", "Mountain");
  ExpectError("date = \"2003-02-29\"\ntime = 12:30:30\ntime_zone = \"UTC\"\n" + place, "sun.date", "2003-02-29");
  ExpectError("date = 2003-10-17\ntime = 12:30:30\ntime_zone = \"UTC\"\nlatitude_deg = -91\nlongitude_deg = 0\n",
              "sun.latitude_deg", "-91");
  ExpectError("zenith_deg = 40\ndate = 2003-10-17\ntime = 12:30:30\ntime_zone = \"UTC\"\n" + place, "sun.date",
              "2003-10-17");
}

}  // namespace
}  // namespace aerial
