#include "aerial/validation/lambertian_radiance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace aerial::validation {
namespace {

const AtmosphereParameters kEarth = AtmosphereParameters::Earth();
const reference::MonteCarloOptions kPaths{.paths_per_query = 1024};
constexpr int kOrders = 3;
constexpr Spectrum kAlbedo{0.1, 0.2, 0.3};

// The sun at zenith cosine mu_s, in the xz plane.
glm::dvec3 Sun(double mu_s) { return {std::sqrt(1.0 - mu_s * mu_s), 0.0, mu_s}; }

// A flat horizontal point 200 m up: albedo / pi (E_direct + E_sky) with both irradiances straight
// from the reference, the sky's from the same paths (equal to rounding). With the disc's centre
// more than 20 degrees above the horizon both direct irradiances take the centre's transmittance
// (solar_disc.cpp): equal to rounding too. Lower, the reference averages the cosine over the disc
// where LambertianRadiance takes the centre's (lambertian_radiance.h): the sun's part is then low
// by 1e-4 to 2.4e-4 at 10 degrees and 1e-3 to 5e-3 at 3 degrees (red to blue), as measured.
TEST(LambertianRadiance, HorizontalIsAlbedoOverPiTimesDirectPlusSkyIrradiance) {
  reference::Reference model(kEarth);
  const double r = kEarth.bottom_radius_m + 200.0;
  for (auto [elevation_deg, tolerance] : {std::pair{37.0, 1e-12}, {10.0, 3e-4}, {3.0, 6e-3}}) {
    double mu_s = std::sin(elevation_deg * std::numbers::pi / 180.0);
    reference::Estimate radiance =
        LambertianRadiance(model, {.point = {0, 0, r}, .normal = {0, 0, 1}, .albedo = kAlbedo}, Sun(mu_s),
                           kOrders, kPaths);
    Spectrum direct = model.ComputeDirectIrradiance(r, mu_s);
    reference::Estimate sky = model.ComputeSkyIrradiance(r, mu_s, kOrders, kPaths);
    for (int c = 0; c < 3; ++c) {
      double reflectance = kAlbedo[c] / std::numbers::pi;
      double sun_part = radiance.value[c] - reflectance * sky.value[c];
      EXPECT_NEAR(sun_part / (reflectance * direct[c]), 1.0, tolerance) << elevation_deg << " deg, channel " << c;
      EXPECT_NEAR(radiance.std_error[c], reflectance * sky.std_error[c], 1e-12 * radiance.value[c]);
    }
  }
}

// Tilted 40 degrees from up toward six azimuths (toward the sun, across, away): the sun's part is
// the horizontal one times n . sun / mu_s (0 facing away from it), the sky's the reference's
// tilted sky irradiance.
TEST(LambertianRadiance, TiltedScalesTheSunByTheCosineOnTheSurface) {
  reference::Reference model(kEarth);
  const double r = kEarth.bottom_radius_m + 200.0, mu_s = 0.6, tilt = 40.0 * std::numbers::pi / 180.0;
  const glm::dvec3 sun = Sun(mu_s);
  Spectrum direct_horizontal = model.ComputeDirectIrradiance(r, mu_s);
  for (int k = 0; k < 6; ++k) {
    double azimuth = k * std::numbers::pi / 5.0;  // 0: toward the sun, pi: away from it
    glm::dvec3 normal(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), std::cos(tilt));
    reference::Estimate radiance =
        LambertianRadiance(model, {.point = {0, 0, r}, .normal = normal, .albedo = kAlbedo}, sun, kOrders, kPaths);
    double cos_sun = glm::dot(normal, sun);
    reference::Estimate sky = model.ComputeTiltedSkyIrradiance(r, mu_s, normal.z, cos_sun, kOrders, kPaths);
    for (int c = 0; c < 3; ++c) {
      double direct = direct_horizontal[c] * std::max(cos_sun, 0.0) / mu_s;
      double expected = kAlbedo[c] / std::numbers::pi * (direct + sky.value[c]);
      EXPECT_NEAR(radiance.value[c] / expected, 1.0, 1e-12) << "azimuth " << azimuth << ", channel " << c;
    }
    if (k == 5) {
      EXPECT_LT(cos_sun, 0.0) << "one normal faces away from the sun";
    }
  }
}

}  // namespace
}  // namespace aerial::validation
