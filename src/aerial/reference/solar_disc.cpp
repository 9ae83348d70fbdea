#include "aerial/reference/solar_disc.h"

#include <numbers>

#include "aerial/reference/geometry.h"
#include "aerial/reference/optical_depth.h"
#include "aerial/reference/quadrature.h"

namespace aerial::reference {
namespace {

// Above this elevation of the disc centre over the horizon, the centre's transmittance is the
// disc's to 2.1e-5 (measured on the ground and at 10 km; solar_disc_test checks it), and the
// quadrature is skipped.
constexpr double kCentreOnlyElevation = 20.0 * std::numbers::pi / 180.0;

// (2 / pi) integral_0^{t_h} sin^2 t V T(mu) w(mu) dt over the visible part of the disc, with
// w(mu) = 1 or max(mu, 0). 8-point Gauss-Legendre in t, on four pieces where the horizon cuts the
// disc (the integrand is smooth in t; the horizon only moves the upper limit).
Spectrum DiscAverage(const Medium& medium, Accuracy accuracy, double r, double mu_s, bool cosine) {
  const double alpha = medium.atmosphere().sun_angular_radius_rad;
  const double theta_s = std::acos(ClampCosine(mu_s));
  const double theta_horizon = std::acos(CosHorizon(r, medium.bottom_radius()));
  if (theta_horizon - theta_s > kCentreOnlyElevation) {
    Spectrum t = ComputeTransmittance(medium, accuracy, r, mu_s,
                                      DistanceToOuterSphere(r, mu_s, medium.top_radius()));
    if (cosine) for (double& v : t) v *= mu_s;
    return t;
  }
  // The disc point at y is visible while theta_s - y alpha < theta_horizon.
  const double y_horizon = (theta_s - theta_horizon) / alpha;
  if (y_horizon >= 1.0) return {};
  const double t_horizon = std::acos(std::max(y_horizon, -1.0));
  Spectrum sum{};
  const int pieces = y_horizon > -1.0 ? 4 : 1;
  for (int p = 0; p < pieces; ++p) {
    ForEachGaussLegendreNode(kGaussLegendre8X, kGaussLegendre8W, t_horizon * p / pieces,
                             t_horizon * (p + 1) / pieces, [&](double t, double weight) {
      double mu = std::cos(theta_s - alpha * std::cos(t));
      double w = std::sin(t) * std::sin(t) * weight * (cosine ? std::max(mu, 0.0) : 1.0);
      if (w == 0.0) return;
      Spectrum transmittance = ComputeTransmittance(medium, accuracy, r, mu,
                                                    DistanceToOuterSphere(r, mu, medium.top_radius()));
      for (int c = 0; c < 3; ++c) sum[c] += w * transmittance[c];
    });
  }
  for (double& s : sum) s *= 2.0 / std::numbers::pi;
  return sum;
}

}  // namespace

Spectrum SunDiscTransmittance(const Medium& medium, Accuracy accuracy, double r, double mu_s) {
  return DiscAverage(medium, accuracy, r, mu_s, false);
}

Spectrum SunDiscHorizontalIrradianceFactor(const Medium& medium, Accuracy accuracy, double r,
                                           double mu_s) {
  return DiscAverage(medium, accuracy, r, mu_s, true);
}

}  // namespace aerial::reference
