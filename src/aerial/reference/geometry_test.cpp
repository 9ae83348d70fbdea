#include "aerial/reference/geometry.h"

#include <gtest/gtest.h>

#include "aerial/reference/vec3.h"

namespace aerial::reference {
namespace {

constexpr double R = 6360e3, Rt = 6420e3;

// Zenith and nadir distances are the radii differences; a horizontal ray from the ground reaches
// the top after sqrt(Rt^2 - R^2). Rounding of ~4e13 m^2 terms: 1e-6 m.
TEST(Geometry, DistancesToSpheres) {
  EXPECT_NEAR(DistanceToOuterSphere(R + 1000.0, 1.0, Rt), Rt - R - 1000.0, 1e-6);
  EXPECT_NEAR(DistanceToInnerSphere(R + 1000.0, -1.0, R), 1000.0, 1e-6);
  EXPECT_NEAR(DistanceToOuterSphere(R, 0.0, Rt), std::sqrt(Rt * Rt - R * R), 1e-6);
  // Point at distance d: radius by the law of cosines, e.g. the tangent point of a horizontal ray.
  EXPECT_NEAR(RadiusAt(R + 1000.0, 0.0, 0.0), R + 1000.0, 1e-6);
}

// The ground is hit exactly below the horizon, mu < -sqrt(1 - (R/r)^2).
TEST(Geometry, GroundIntersectionStartsBelowTheHorizon) {
  double r = R + 10e3, horizon = CosHorizon(r, R);
  EXPECT_TRUE(RayIntersectsInnerSphere(r, horizon - 1e-9, R));
  EXPECT_FALSE(RayIntersectsInnerSphere(r, horizon + 1e-9, R));
  EXPECT_FALSE(RayIntersectsInnerSphere(R, 0.0, R));
  EXPECT_TRUE(RayIntersectsInnerSphere(R, -1e-9, R));
}

// AroundAxis returns unit vectors at the asked cosine from the axis, for any axis.
TEST(Vec3, AroundAxisKeepsTheCosine) {
  for (Vec3 n : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, Normalize(Vec3{1, -2, 0.5})}) {
    Vec3 w = AroundAxis(n, 0.3, 1.7);
    EXPECT_NEAR(Length(w), 1.0, 1e-14);
    EXPECT_NEAR(Dot(w, n), 0.3, 1e-14);
  }
}

}  // namespace
}  // namespace aerial::reference
