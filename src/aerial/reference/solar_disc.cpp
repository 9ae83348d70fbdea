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

// Below this elevation the transmittance varies fast enough across the disc to need 8 nodes.
constexpr double kFewNodesElevation = 3.0 * std::numbers::pi / 180.0;

// (2 / pi) integral_{-1}^{1} sqrt(1 - y^2) T(mu(y)) w(mu(y)) dy over a wholly visible disc, with
// w(mu) = 1 or max(mu, 0), by the n-node Gauss-Chebyshev rule of the second kind (Abramowitz &
// Stegun 25.4.40; exact for polynomials of degree 2n - 1 in y): y_i = cos(i pi / (n + 1)),
// weights pi / (n + 1) sin^2(i pi / (n + 1)).
template <typename Node>
void ForEachChebyshevNode(int n, Node&& node) {
  for (int i = 1; i <= n; ++i) {
    double angle = i * std::numbers::pi / (n + 1);
    node(std::cos(angle), std::numbers::pi / (n + 1) * std::sin(angle) * std::sin(angle));
  }
}

// The disc average as a weighted sum over disc points: node(weight, column) for each, the column
// of the point's slant to the top of the atmosphere; none where the whole disc is below the
// horizon. Wholly visible: Gauss-Chebyshev, 3 nodes above kFewNodesElevation and 8 below. Cut by
// the horizon: with y = cos t, (2 / pi) integral_0^{t_h} sin^2 t T(mu) w(mu) dt, t_h the horizon's
// t, by 4 x 8-node Gauss-Legendre (the integrand is smooth in t; the horizon only moves the upper
// limit). solar_disc_test bounds each case against a brute-force integral.
// Where the disc is cut off, as a zenith angle: the planet's horizon, and for a horizontal surface
// also its plane (max(mu, 0) has a kink there).
double CutOffZenith(const Medium& medium, double r, bool cosine) {
  double theta_horizon = std::acos(CosHorizon(r, medium.bottom_radius()));
  return cosine ? std::min(theta_horizon, std::numbers::pi / 2.0) : theta_horizon;
}

Column Slant(const Medium& medium, Accuracy accuracy, double r, double mu) {
  return ComputeColumn(medium, accuracy, r, mu, DistanceToOuterSphere(r, mu, medium.top_radius()));
}

template <typename Node>
void ForEachDiscNode(const Medium& medium, Accuracy accuracy, double r, double mu_s, bool cosine, Node&& node) {
  const double alpha = medium.atmosphere().sun_angular_radius_rad;
  const double theta_s = std::acos(ClampCosine(mu_s));
  const double theta_horizon = CutOffZenith(medium, r, cosine);
  auto slant = [&](double mu) { return Slant(medium, accuracy, r, mu); };
  if (theta_horizon - theta_s > kCentreOnlyElevation) {
    node(cosine ? mu_s : 1.0, slant(mu_s));
    return;
  }
  // The disc point at y is visible while theta_s - y alpha < theta_horizon.
  const double y_horizon = (theta_s - theta_horizon) / alpha;
  if (y_horizon >= 1.0) return;
  const double t_horizon = std::acos(std::max(y_horizon, -1.0));
  // The disc point at y, with quadrature weight `weight` for sqrt(1 - y^2) dy.
  auto add_point = [&](double y, double weight) {
    double mu = std::cos(theta_s - alpha * y);
    node(2.0 / std::numbers::pi * weight * (cosine ? std::max(mu, 0.0) : 1.0), slant(mu));
  };
  if (y_horizon <= -1.0) {
    ForEachChebyshevNode(theta_horizon - theta_s > kFewNodesElevation ? 3 : 8, add_point);
  } else {
    const int pieces = 4;
    for (int p = 0; p < pieces; ++p) {
      ForEachGaussLegendreNode(kGaussLegendre8X, kGaussLegendre8W, t_horizon * p / pieces,
                               t_horizon * (p + 1) / pieces, [&](double t, double weight) {
        add_point(std::cos(t), weight * std::sin(t) * std::sin(t));
      });
    }
  }
}

Spectrum DiscAverage(const Medium& medium, Accuracy accuracy, double r, double mu_s, bool cosine) {
  Spectrum sum{};
  ForEachDiscNode(medium, accuracy, r, mu_s, cosine, [&](double weight, const Column& column) {
    Spectrum t = medium.Transmittance(column);
    for (int c = 0; c < 3; ++c) sum[c] += weight * t[c];
  });
  return sum;
}

Channels SampleDisc(const WavelengthGroups& groups, double r, double mu_s, bool cosine, Rng& rng) {
  const Medium& medium = groups.sampling();
  const double theta_s = std::acos(ClampCosine(mu_s));
  const double theta_horizon = CutOffZenith(medium, r, cosine);
  double mu = mu_s;
  if (theta_horizon - theta_s <= kCentreOnlyElevation) {
    // A point uniform over the unit disc: radius sqrt(u), angle 2 pi v; its y is the elevation.
    const double radius = std::sqrt(rng.Uniform()), angle = 2.0 * std::numbers::pi * rng.Uniform();
    const double theta = theta_s - medium.atmosphere().sun_angular_radius_rad * radius * std::sin(angle);
    if (theta >= theta_horizon) return Channels(groups.channels());
    mu = std::cos(theta);
  }
  Channels t = groups.Transmittance(Slant(medium, Accuracy::kMonteCarlo, r, mu));
  if (cosine)
    for (int c = 0; c < t.size(); ++c) t[c] *= std::max(mu, 0.0);
  return t;
}

}  // namespace

Spectrum SunDiscTransmittance(const Medium& medium, Accuracy accuracy, double r, double mu_s) {
  return DiscAverage(medium, accuracy, r, mu_s, false);
}

Spectrum SunDiscHorizontalIrradianceFactor(const Medium& medium, Accuracy accuracy, double r,
                                           double mu_s) {
  return DiscAverage(medium, accuracy, r, mu_s, true);
}

Channels SampleSunDiscTransmittance(const WavelengthGroups& groups, double r, double mu_s, Rng& rng) {
  return SampleDisc(groups, r, mu_s, false, rng);
}

Channels SampleSunDiscHorizontalIrradianceFactor(const WavelengthGroups& groups, double r, double mu_s, Rng& rng) {
  return SampleDisc(groups, r, mu_s, true, rng);
}

}  // namespace aerial::reference
