#include "aerial/reference/distance_sampler.h"

#include <gtest/gtest.h>

#include "aerial/reference/quadrature.h"

namespace aerial::reference {
namespace {

// The sampling density is normalized on the segment and Sample reports the density Pdf gives at
// the sample, for a ray grazing the ground (long, with the densities' steepest variation).
// 1e-9: the adaptive quadrature's tolerance on a piecewise log-linear function.
TEST(DistanceSampler, PdfIsNormalizedAndConsistent) {
  Medium medium(AtmosphereParameters::Earth());
  double r = medium.bottom_radius() + 2000.0, mu = -0.01;
  double length = DistanceToOuterSphere(r, mu, medium.top_radius());
  RayColumns columns;
  columns.Build(medium, Accuracy::kMonteCarlo, r, mu, length);
  DistanceSampler sampler;
  sampler.Build(medium, columns);
  Values<1> total = IntegrateAdaptive<1>([&](double s) { return Values<1>{sampler.Pdf(s)}; }, columns.cuts(), 1e-11);
  EXPECT_NEAR(total[0], 1.0, 1e-9);
  for (double u = 0.0; u < 1.0; u += 0.013) {
    double pdf;
    double s = sampler.Sample(u, &pdf);
    EXPECT_GE(s, 0.0);
    EXPECT_LE(s, length);
    EXPECT_DOUBLE_EQ(pdf, sampler.Pdf(s));
  }
}

}  // namespace
}  // namespace aerial::reference
