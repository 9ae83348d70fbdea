#include "aerial/validation/reference_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "aerial/probe/spectral_reference.h"
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

// The spectral reference of a sky pixel is the spectral probe's along the same ray: two paths to
// the same sum over the groups (SampleReference with the ray's distance to the atmosphere's top,
// ProbeReference with none), both deterministic quadratures with single scattering, so they agree
// to rounding (1e-9). A ray that meets the bare planet adds the lit ground seen through the air
// (the ground's albedo at each group's wavelengths), above the probe's inscatter alone; the
// transmittance is the sunlit one, like the probe's. (The probe's path count sets only the Monte
// Carlo of its sky irradiance, not compared here: the fewest paths it takes.)
TEST(SampleSpectralReference, SkyPixelsAreTheSpectralProbesRadiance) {
  const AtmosphereParameters earth = AtmosphereParameters::Earth();
  Scene scene;
  scene.camera = {.position = {0, 0, 500}, .yaw_deg = 20, .pitch_deg = -3, .vertical_fov_deg = 40};
  scene.sun = {.zenith_deg = 70, .azimuth_deg = 60};
  FrameUniforms frame = MakeFrameUniforms(scene, earth.bottom_radius_m, 32, 18, FroxelGrid{});
  ImageRgbF all_sky{.width = 32, .height = 18, .rgba = std::vector<float>(32 * 18 * 4, -1.0f)};
  ViewReference view =
      SampleSpectralReference(earth, spectrum::SpectralSampling::ForTables(12), scene, frame, all_sky,
                              {.columns = 3, .rows = 2, .orders = 1}, {});
  ASSERT_EQ(view.pixels.size(), 6u);
  const glm::dvec3 camera(frame.camera_planet_position[0], frame.camera_planet_position[1],
                          frame.camera_planet_position[2]);
  const glm::dvec3 sun(frame.sun_direction[0], frame.sun_direction[1], frame.sun_direction[2]);
  const double r = glm::length(camera);
  int ground_pixels = 0;
  for (const ReferencePixel& pixel : view.pixels) {
    glm::dvec3 ray = PixelRay(frame, pixel.x, pixel.y);
    RayParameters parameters{r, glm::dot(camera, ray) / r, glm::dot(camera, sun) / r, glm::dot(ray, sun)};
    ProbeResult probe =
        ProbeReferenceSpectral(earth, parameters, std::nullopt, spectrum::SpectralSampling::ForTables(12),
                               {.orders = 1, .paths_per_query = 512});
    const bool ground = parameters.mu < -std::sqrt(1.0 - std::pow(earth.bottom_radius_m / r, 2.0));
    ground_pixels += ground;
    Spectrum expected = pixel.Expected();
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(pixel.transmittance[c], probe.transmittance[c], 1e-9) << pixel.x << "," << pixel.y;
      if (ground)
        EXPECT_GT(expected[c], 1.05 * probe.sky_radiance[c]) << pixel.x << "," << pixel.y;
      else
        EXPECT_NEAR(expected[c], probe.sky_radiance[c], 1e-9 * probe.sky_radiance[c]) << pixel.x << "," << pixel.y;
    }
  }
  EXPECT_GT(ground_pixels, 0);
  EXPECT_LT(ground_pixels, 6);
}

}  // namespace
}  // namespace aerial::validation
