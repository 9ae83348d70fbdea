#include "aerial/reference/medium.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace aerial::reference {
namespace {

// The inlined profile must be DensityProfile::Density itself: same formula, same layer switch.
// Only the rounding of a skipped 0 * exp() may differ, hence 1e-15.
TEST(ProfileDensity, MatchesDensityProfile) {
  AtmosphereParameters a = AtmosphereParameters::Earth();
  for (const DensityProfile* p : {&a.rayleigh_density, &a.mie_density, &a.absorption_density}) {
    for (double h = 0.0; h <= 61000.0; h += 37.5) EXPECT_NEAR(ProfileDensity(*p, h), p->Density(h), 1e-15) << h;
  }
}

// Below the ground (rounding at ray ends) the density is the ground's, not that of a profile's
// lower layer (zero for Earth's Rayleigh and Mie, whose layers[0].width_m is 0).
TEST(Medium, DensityBelowGroundIsTheGrounds) {
  Medium medium(AtmosphereParameters::Earth());
  Densities below = medium.At(-1e-9), ground = medium.At(0.0);
  EXPECT_EQ(below.rayleigh, 1.0);
  EXPECT_EQ(below.mie, ground.mie);
}

// The ozone tent's kinks (10, 25, 40 km) must be levels so that no piece straddles one, and
// consecutive levels must be at most 2 (reference) or 4 (Monte Carlo) Mie scale heights apart
// where the Mie layer matters: up to the top for the reference, and for Monte Carlo up to where
// Mie's extinction falls under 1e-6 of Rayleigh's, 4.44e-6 e^(-h / 1.2 km) < 1e-6 x 5.8e-6
// e^(-h / 8 km) above 19.0 km.
TEST(Medium, LevelsHoldKinksAndScaleHeights) {
  AtmosphereParameters a = AtmosphereParameters::Earth();
  Medium medium(a);
  for (Accuracy accuracy : {Accuracy::kReference, Accuracy::kMonteCarlo}) {
    const std::vector<double>& radii = medium.level_radii(accuracy);
    ASSERT_TRUE(std::is_sorted(radii.begin(), radii.end()));
    EXPECT_EQ(radii.front(), a.bottom_radius_m);
    EXPECT_EQ(radii.back(), a.top_radius_m);
    for (double kink : {10e3, 25e3, 40e3}) {
      auto it = std::lower_bound(radii.begin(), radii.end(), a.bottom_radius_m + kink - 1e-3);
      ASSERT_NE(it, radii.end());
      EXPECT_NEAR(*it, a.bottom_radius_m + kink, 1e-3) << kink;
    }
    bool reference = accuracy == Accuracy::kReference;
    double max_gap = reference ? 2.0 * 1200.0 : 4.0 * 1200.0;
    double refined_up_to = reference ? 60e3 : 19e3;
    for (size_t i = 0; i + 1 < radii.size() && radii[i] - a.bottom_radius_m < refined_up_to; ++i)
      EXPECT_LE(radii[i + 1] - radii[i], max_gap + 1e-6);
  }
  // Where Mie is negligible, Monte Carlo rays are not cut for it: no level between the last Mie
  // level (19.2 km) and the ozone kink at 25 km.
  const std::vector<double>& radii = medium.level_radii(Accuracy::kMonteCarlo);
  EXPECT_EQ(std::count_if(radii.begin(), radii.end(),
                          [&](double r) { return r > a.bottom_radius_m + 19.5e3 && r < a.bottom_radius_m + 24.9e3; }),
            0);
}

}  // namespace
}  // namespace aerial::reference
