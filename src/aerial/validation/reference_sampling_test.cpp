#include "aerial/validation/reference_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "aerial/render/frame_uniforms.h"
#include "aerial/scene/camera.h"

namespace aerial::validation {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The frame uniforms hold float matrices; a ray rebuilt from them is good to ~1e-6.
constexpr double kFloatMatrix = 1e-5;

TEST(PixelRay, TopRowLooksUpByHalfTheFieldOfView) {
  Scene scene;
  scene.camera = {.position = {0, 0, 100}, .yaw_deg = 0, .pitch_deg = 0, .vertical_fov_deg = 50};
  FrameUniforms frame = MakeFrameUniforms(scene, 6360e3, 200, 100, FroxelGrid{});
  // Pixel (100, 0): half a pixel right of the center column, half a pixel below the top edge.
  glm::dvec3 ray = PixelRay(frame, 100, 0);
  double tan_half = std::tan(25.0 * kDeg);
  // clip x = 2 * 100.5 / 200 - 1 = 0.005, view x = clip x * aspect * tan(fov / 2); clip y = -0.99.
  glm::dvec3 view(0.005 * 2.0 * tan_half, 0.99 * tan_half, -1.0);
  view = glm::normalize(view);
  // View space (x right, y up, -z forward) to the world (x east, y north, z up) looking north.
  EXPECT_NEAR(ray.x, view.x, kFloatMatrix);
  EXPECT_NEAR(ray.y, -view.z, kFloatMatrix);
  EXPECT_NEAR(ray.z, view.y, kFloatMatrix);
}

TEST(PixelRay, CenterFollowsTheCamera) {
  Scene scene;
  scene.camera = {.position = {0, 0, 100}, .yaw_deg = 235, .pitch_deg = -12, .vertical_fov_deg = 40};
  FrameUniforms frame = MakeFrameUniforms(scene, 6360e3, 101, 51, FroxelGrid{});
  glm::dvec3 ray = PixelRay(frame, 50, 25);  // the exact center of an odd-sized image
  glm::dvec3 forward = Forward(scene.camera);
  EXPECT_NEAR(glm::dot(ray, forward), 1.0, kFloatMatrix);
}

TEST(GridPixels, CellCentersInRowOrder) {
  auto pixels = GridPixels(320, 180, 8, 5);
  ASSERT_EQ(pixels.size(), 40u);
  EXPECT_EQ(pixels.front(), (std::array<int, 2>{20, 18}));  // (0.5 * 320 / 8, 0.5 * 180 / 5)
  EXPECT_EQ(pixels[1], (std::array<int, 2>{60, 18}));
  EXPECT_EQ(pixels.back(), (std::array<int, 2>{300, 162}));
}

}  // namespace
}  // namespace aerial::validation
