// The CPU reference as the public API gives it (aerial/probe.h, ProbeReference and
// ReferenceOptions): the options an embedder sets are the ones the estimate follows.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "aerial/error.h"
#include "aerial/probe.h"

namespace aerial {
namespace {

// Daylight: 1 km up, looking 20 degrees above the horizon, the sun 40 degrees above it.
RayParameters DaylightRay(const AtmosphereParameters& earth) {
  return ToRayParameters({.altitude_m = 1000.0, .view_zenith_deg = 70.0, .sun_zenith_deg = 50.0, .azimuth_deg = 30.0},
                         earth);
}

ProbeResult Reference(const ReferenceOptions& options) {
  const AtmosphereParameters earth = AtmosphereParameters::Earth();
  return ProbeReference(earth, DaylightRay(earth), std::nullopt, options);
}

// A result follows the seed and the path count, and not the thread count (each chunk of paths
// draws from its own stream).
TEST(PublicReference, FollowsSeedAndPathsButNotThreads) {
  const ReferenceOptions base{.orders = 2, .paths_per_query = 2048, .seed = 1, .threads = 1};
  const ProbeResult one = Reference(base);
  ReferenceOptions options = base;
  options.threads = 3;
  const ProbeResult threads = Reference(options);
  options = base;
  options.seed = 2;
  const ProbeResult seed = Reference(options);
  options = base;
  options.paths_per_query = 4 * base.paths_per_query;
  const ProbeResult paths = Reference(options);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(threads.sky_radiance[c], one.sky_radiance[c]);
    EXPECT_EQ(threads.sky_irradiance[c], one.sky_irradiance[c]);
    // Another seed is another, independent estimate of the same value.
    EXPECT_NE(seed.sky_radiance[c], one.sky_radiance[c]);
    EXPECT_LT(std::abs(seed.sky_radiance[c] - one.sky_radiance[c]),
              4.0 * std::hypot(seed.sky_radiance_std_error[c], one.sky_radiance_std_error[c]));
    // Four times the paths halve the standard error. Each error is estimated from the spread of
    // 8 (or 32) chunk means, so it is itself uncertain by about 1 / sqrt(2 (8 - 1)) = 27 % (13 %):
    // [0.3, 0.8] holds the ratio 0.5 with room for both, and excludes 1 (the path count ignored).
    const double ratio = paths.sky_radiance_std_error[c] / one.sky_radiance_std_error[c];
    EXPECT_GT(ratio, 0.3) << c;
    EXPECT_LT(ratio, 0.8) << c;
  }
}

// orders bounds the series: order 1 alone is a deterministic quadrature (no standard error), and
// each order added brings light. Orders 3 and above add a few percent here; 32768 paths put the
// standard errors near 0.3 % of the radiance, so 4 of them stay below it.
TEST(PublicReference, OrdersBoundTheSeries) {
  const ProbeResult single = Reference({.orders = 1, .paths_per_query = 2048});
  const ProbeResult two = Reference({.orders = 2, .paths_per_query = 32768});
  const ProbeResult all = Reference({.paths_per_query = 32768});
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(single.sky_radiance_std_error[c], 0.0);
    EXPECT_GT(single.sky_radiance[c], 0.0);
    EXPECT_GT(two.sky_radiance[c], single.sky_radiance[c] + 4.0 * two.sky_radiance_std_error[c]);
    EXPECT_GT(all.sky_radiance[c], two.sky_radiance[c] + 4.0 * std::hypot(all.sky_radiance_std_error[c],
                                                                         two.sky_radiance_std_error[c]));
  }
}

TEST(PublicReference, RejectsBadOptionsNamingTheField) {
  auto field = [](const ReferenceOptions& options) {
    try {
      Reference(options);
    } catch (const Error& e) {
      return e.field();
    }
    return std::string("no error");
  };
  EXPECT_EQ(field({.orders = 0}), "orders");
  EXPECT_EQ(field({.paths_per_query = 0}), "paths_per_query");
  EXPECT_EQ(field({.threads = -1}), "threads");
}

}  // namespace
}  // namespace aerial
