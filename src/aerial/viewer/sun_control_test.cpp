#include "aerial/viewer/sun_control.h"

#include <gtest/gtest.h>

namespace aerial::viewer {
namespace {

// Closed forms of the solar position (sun_control.h): at solar noon the zenith angle is
// |latitude - declination| and the sun is due south north of the declination; at the equinox
// (declination 0) it rises due east at 6 h and sets due west at 18 h, from any latitude.
TEST(SunAtSolarTime, MatchesClosedForms) {
  Sun noon = SunAtSolarTime(12.0, 45.0, 0.0);
  EXPECT_NEAR(noon.zenith_deg, 45.0, 1e-9);
  EXPECT_NEAR(noon.azimuth_deg, 180.0, 1e-9);
  Sun summer = SunAtSolarTime(12.0, 45.0, 23.44);
  EXPECT_NEAR(summer.zenith_deg, 45.0 - 23.44, 1e-9);
  Sun sunrise = SunAtSolarTime(6.0, 45.0, 0.0);
  EXPECT_NEAR(sunrise.zenith_deg, 90.0, 1e-9);
  EXPECT_NEAR(sunrise.azimuth_deg, 90.0, 1e-9);
  Sun sunset = SunAtSolarTime(18.0, 30.0, 0.0);
  EXPECT_NEAR(sunset.zenith_deg, 90.0, 1e-9);
  EXPECT_NEAR(sunset.azimuth_deg, 270.0, 1e-9);
  EXPECT_GT(SunAtSolarTime(0.0, 45.0, 0.0).zenith_deg, 90.0);  // midnight: below the horizon
}

TEST(SteerSun, WrapsAzimuthAndClampsZenith) {
  Sun sun{.zenith_deg = 100.0, .azimuth_deg = 350.0};
  SteerSun(sun, 20.0, 30.0, 120.0);
  EXPECT_NEAR(sun.azimuth_deg, 10.0, 1e-9);
  EXPECT_EQ(sun.zenith_deg, 120.0);
  SteerSun(sun, -20.0, -200.0, 120.0);
  EXPECT_NEAR(sun.azimuth_deg, 350.0, 1e-9);
  EXPECT_EQ(sun.zenith_deg, 0.0);
}

}  // namespace
}  // namespace aerial::viewer
