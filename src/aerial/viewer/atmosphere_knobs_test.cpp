#include "aerial/viewer/atmosphere_knobs.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aerial::viewer {
namespace {

TEST(AtmosphereKnobs, UnchangedKnobsGiveTheBaseExactly) {
  AtmosphereParameters earth = AtmosphereParameters::Earth();
  AtmosphereKnobs knobs = ReadKnobs(earth);
  EXPECT_DOUBLE_EQ(*knobs.rayleigh_scale_height_m, 8000.0);
  EXPECT_DOUBLE_EQ(*knobs.mie_scale_height_m, 1200.0);
  EXPECT_DOUBLE_EQ(knobs.mie_g, 0.8);
  EXPECT_DOUBLE_EQ(knobs.ground_albedo, 0.1);
  // Same hash, hence the same cached tables.
  EXPECT_EQ(ApplyKnobs(earth, knobs).Hash(), earth.Hash());
}

TEST(AtmosphereKnobs, ChangeTheProfilesAndCoefficients) {
  AtmosphereParameters earth = AtmosphereParameters::Earth();
  AtmosphereKnobs knobs = ReadKnobs(earth);
  knobs.rayleigh_scale_height_m = 10e3;
  knobs.mie_scale_height_m = 2e3;
  knobs.ozone_scale = 0.0;
  knobs.ground_albedo = 0.3;
  knobs.mie_g = 0.7;
  AtmosphereParameters a = ApplyKnobs(earth, knobs);
  // density(h) = exp(-h / H): at h = H it is 1/e.
  EXPECT_NEAR(a.rayleigh_density.Density(10e3), std::exp(-1.0), 1e-12);
  EXPECT_NEAR(a.mie_density.Density(2e3), std::exp(-1.0), 1e-12);
  EXPECT_EQ(a.absorption_extinction[1], 0.0);
  EXPECT_EQ(a.ground_albedo[2], 0.3);
  EXPECT_EQ(a.mie_phase_g, 0.7);
  EXPECT_NE(a.Hash(), earth.Hash());
  // The ozone profile's linear layers have no exponential term and are left alone.
  EXPECT_EQ(a.absorption_density.layers[0].exp_scale_per_m, earth.absorption_density.layers[0].exp_scale_per_m);
}

}  // namespace
}  // namespace aerial::viewer
