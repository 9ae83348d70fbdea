#include "aerial/cli/scene_overrides.h"

#include <gtest/gtest.h>

#include "aerial/cli/sun_date_options.h"
#include "aerial/error.h"

namespace aerial::cli {
namespace {

constexpr double kR = 6360e3;
const astronomy::SunDate kGolden{"2003-10-17", "12:30:30", "-07:00", 39.742476, -105.1786};

TEST(SceneOverrides, SetValuesReplaceAndOthersStay) {
  Scene scene;
  Camera before = scene.camera;
  SceneOverrides overrides;
  overrides.camera_yaw_deg = 90.0;
  overrides.sun_zenith_deg = 91.0;
  ApplyOverrides(scene, overrides, kR);
  EXPECT_EQ(scene.camera.yaw_deg, 90.0);
  EXPECT_EQ(scene.sun.zenith_deg, 91.0);
  EXPECT_EQ(scene.camera.position, before.position);
  EXPECT_EQ(scene.camera.pitch_deg, before.pitch_deg);
  EXPECT_EQ(scene.camera.vertical_fov_deg, before.vertical_fov_deg);
}

// Each invalid value is named by its option, and nothing is applied.
TEST(SceneOverrides, InvalidValuesAreNamedAndNothingChanges) {
  struct Case {
    SceneOverrides overrides;
    std::string field;
  };
  std::vector<Case> cases(8);
  cases[0] = {{.camera_position_m = glm::dvec3(0, 0, 2e5)}, "--camera-position-m"};
  cases[1] = {{.camera_yaw_deg = NAN}, "--camera-yaw-deg"};
  cases[2] = {{.camera_pitch_deg = -91.0}, "--camera-pitch-deg"};
  cases[3] = {{.camera_fov_deg = 0.5}, "--camera-fov-deg"};
  cases[4] = {{.sun_zenith_deg = 200.0}, "--sun-zenith-deg"};
  cases[5] = {{.sun_azimuth_deg = INFINITY}, "--sun-azimuth-deg"};
  cases[6] = {{.camera_yaw_deg = 5.8e307}, "--camera-yaw-deg"};  // finite, yet NaN frames
  cases[7] = {{.sun_azimuth_deg = -1e308}, "--sun-azimuth-deg"};
  for (Case& c : cases) {
    c.overrides.camera_yaw_deg = c.overrides.camera_yaw_deg.value_or(45.0);  // a valid change
    Scene scene;
    try {
      ApplyOverrides(scene, c.overrides, kR);
      ADD_FAILURE() << c.field << ": no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), c.field);
      EXPECT_EQ(e.where(), "command line");
    }
    EXPECT_EQ(scene.camera.yaw_deg, Camera{}.yaw_deg) << c.field << ": applied before failing";
  }
}

// The sun of a date and a place: the astronomy module's, never together with the angles.
TEST(SceneOverrides, ADateReplacesTheSunAndRefusesAngles) {
  Scene scene;
  SceneOverrides dated{.sun_date = kGolden};
  ApplyOverrides(scene, dated, kR);
  const Sun expected = astronomy::SunFromDate(kGolden, kSunDateOptions, "");
  EXPECT_EQ(scene.sun, expected);

  SceneOverrides both{.sun_zenith_deg = 30.0, .sun_date = kGolden};
  Scene untouched;
  try {
    ApplyOverrides(untouched, both, kR);
    ADD_FAILURE() << "angles and a date accepted together";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "--date");
    EXPECT_EQ(e.value(), "2003-10-17");
  }
  EXPECT_EQ(untouched.sun, Sun{});

  SceneOverrides bad{.sun_date = astronomy::SunDate{"2003-10-17", "12:00", "Europe/Nowhere", 0, 0}};
  EXPECT_THROW(ApplyOverrides(untouched, bad, kR), Error);
  EXPECT_EQ(untouched.sun, Sun{});
}

}  // namespace
}  // namespace aerial::cli
