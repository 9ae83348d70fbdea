#include "aerial/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "aerial/error.h"
#include "aerial/scene/camera.h"
#include "aerial/scene/scene_limits.h"

namespace aerial {
namespace {

constexpr double kR = 6360e3;

double Altitude(const glm::dvec3& p) { return glm::length(p - glm::dvec3(0, 0, -kR)) - kR; }

glm::dvec2 Horizontal(const glm::dvec3& v) { return glm::normalize(glm::dvec2(v)); }

Scene View(const std::string& name) {
  Scene scene;
  ApplyPresetView(scene, name, kR);
  return scene;
}

TEST(Preset, EveryNamedPresetBuildsAValidScene) {
  ASSERT_EQ(PresetNames().size(), 7u);
  for (const std::string& name : PresetNames()) {
    Scene scene = BuildPreset(name, kR);
    EXPECT_EQ(scene.name, name);
    EXPECT_TRUE(scene.terrain) << name;
    EXPECT_EQ(scene.meshes.size(), 12u) << name;  // 6 landmarks, 2 pane frames, 4 transparent
    const Camera& c = scene.camera;
    // The same limits a scene file must meet; these throw on violation.
    EXPECT_NO_THROW(CheckCameraPosition(c.position, kR, name + " camera", ""));
    EXPECT_NO_THROW(CheckPitchDeg(c.pitch_deg, name + " pitch", ""));
    EXPECT_NO_THROW(CheckFovDeg(c.vertical_fov_deg, name + " fov", ""));
    EXPECT_NO_THROW(CheckNearM(c.near_m, name + " near", ""));
    EXPECT_NO_THROW(CheckZenithDeg(scene.sun.zenith_deg, name + " sun", ""));
  }
}

TEST(Preset, UnknownNameIsAnErrorListingTheNames) {
  try {
    BuildPreset("dusk", kR);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "preset name");
    EXPECT_EQ(e.value(), "dusk");
    for (const std::string& name : PresetNames())
      EXPECT_NE(e.allowed().find(name), std::string::npos) << name;
  }
}

TEST(Preset, DefaultSceneIsNoon) {
  Scene noon = View("noon");
  Scene built = BuildDefaultScene(kR);
  EXPECT_EQ(built.camera.position, noon.camera.position);
  EXPECT_EQ(built.camera.yaw_deg, noon.camera.yaw_deg);
  EXPECT_EQ(built.camera.pitch_deg, noon.camera.pitch_deg);
  EXPECT_EQ(built.sun.zenith_deg, noon.sun.zenith_deg);
  EXPECT_EQ(built.sun.azimuth_deg, noon.sun.azimuth_deg);
}

TEST(Preset, SunZenithGrowsFromNoonToTwilight) {
  EXPECT_NEAR(View("noon").sun.zenith_deg, 20.0, 5.0);
  EXPECT_NEAR(View("afternoon").sun.zenith_deg, 55.0, 5.0);
  EXPECT_NEAR(View("sunset").sun.zenith_deg, 89.5, 1.0);
  EXPECT_NEAR(View("twilight").sun.zenith_deg, 92.0, 1.0);
}

TEST(Preset, TwilightLooksAwayFromTheSetSun) {
  Scene twilight = View("twilight");
  EXPECT_GT(twilight.sun.zenith_deg, 90.0);  // below the horizon: the Earth's shadow is on the sky
  // Horizontally opposite within 30 degrees, so the antisolar point is in the image.
  double facing = glm::dot(Horizontal(Forward(twilight.camera)), Horizontal(twilight.sun.Direction()));
  EXPECT_LT(facing, -std::cos(30.0 * std::numbers::pi / 180.0));
}

TEST(Preset, SunsetLooksAtTheSunOnTheHorizon) {
  Scene sunset = View("sunset");
  EXPECT_LT(sunset.sun.zenith_deg, 90.0);  // the disc above the (sea-level) horizon
  EXPECT_GT(sunset.sun.zenith_deg, 88.0);  // but low enough to be reddened
  // Within 10 degrees of the camera's heading: in the frame.
  double facing = glm::dot(Horizontal(Forward(sunset.camera)), Horizontal(sunset.sun.Direction()));
  EXPECT_GT(facing, std::cos(10.0 * std::numbers::pi / 180.0));
}

TEST(Preset, HighAltitudeLooksAtTheHorizonFrom30Km) {
  const Camera camera = View("high-altitude").camera;
  EXPECT_NEAR(Altitude(camera.position), 30e3, 1e-6);
  // The view ray grazes the planet: its closest approach to the center is R. Rounding the pitch
  // through degrees moves the ray by ~1e-16 rad * 620 km, and the difference of 6e6 m vectors
  // below loses ~1e-9 m: 1 mm is a wide margin.
  glm::dvec3 to_center = glm::dvec3(0, 0, -kR) - camera.position;
  glm::dvec3 forward = Forward(camera);
  double miss = glm::length(to_center - forward * glm::dot(to_center, forward));
  EXPECT_NEAR(miss, kR, 1e-3);
  EXPECT_LT(camera.pitch_deg, 0.0);
}

}  // namespace
}  // namespace aerial
