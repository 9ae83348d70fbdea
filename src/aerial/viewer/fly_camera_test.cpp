#include "aerial/viewer/fly_camera.h"

#include <gtest/gtest.h>

#include "aerial/scene/camera.h"

namespace aerial::viewer {
namespace {

constexpr double kR = 6360e3;

TEST(Fly, MovesAtTheChosenSpeedAlongTheView) {
  Camera camera;
  camera.position = {0, 0, 100};
  camera.yaw_deg = 90.0;  // east
  camera.pitch_deg = 0.0;
  Fly(camera, {.forward = 1.0}, 1.0, kR);
  EXPECT_NEAR(camera.position.x, 200.0, 1e-9);
  Fly(camera, {.forward = 1.0, .fast = true}, 0.5, kR);
  EXPECT_NEAR(camera.position.x, 1200.0, 1e-9);
  Fly(camera, {.right = 1.0, .slow = true}, 1.0, kR);  // right of east is south
  EXPECT_NEAR(camera.position.y, -20.0, 1e-9);
  Fly(camera, {.up = -1.0}, 0.25, kR);
  EXPECT_NEAR(camera.position.z, 50.0, 1e-9);
}

TEST(Fly, TurnsAndKeepsPitchAndAltitudeInRange) {
  Camera camera;
  camera.yaw_deg = 350.0;
  camera.pitch_deg = 80.0;
  Fly(camera, {.look_dx_px = 100.0, .look_dy_px = -100.0}, 0.0, kR);  // 15 degrees each
  EXPECT_NEAR(camera.yaw_deg, 5.0, 1e-9);
  EXPECT_EQ(camera.pitch_deg, 89.0);
  camera.position = {0, 0, 99.9e3};
  camera.pitch_deg = 0.0;
  Fly(camera, {.up = 1.0, .fast = true}, 1.0, kR);  // 2 km up, clamped at 100 km
  EXPECT_NEAR(glm::length(camera.position - glm::dvec3(0, 0, -kR)) - kR, 100e3, 1e-6);
}

}  // namespace
}  // namespace aerial::viewer
