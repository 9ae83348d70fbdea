#include "aerial/reference/single_scattering.h"

#include "aerial/reference/geometry.h"
#include "aerial/reference/optical_depth.h"
#include "aerial/reference/quadrature.h"
#include "aerial/reference/solar_disc.h"

namespace aerial::reference {
namespace {

// Where the view ray enters or leaves the penumbra, i.e. where the elevation of the disc centre
// over the horizon, in disc radii, x ~ (mu_s_p - cos_theta_h) / (sin_theta_h alpha), crosses -1
// or +1 (solar_disc.h; the integrand has kinks there).
// Sign changes on a 1024-step scan, refined by bisection.
void AddPenumbraEdges(const Medium& medium, double r, double mu, double mu_s, double nu,
                      double length, std::vector<double>* cuts) {
  const double bottom = medium.bottom_radius();
  const double alpha = medium.atmosphere().sun_angular_radius_rad;
  auto x = [&](double s) {
    double r_p = RadiusAt(r, mu, s);
    double sin_theta_h = std::min(bottom / r_p, 1.0);
    double mu_s_p = ClampCosine((r * mu_s + s * nu) / r_p);
    return (mu_s_p - CosHorizon(r_p, bottom)) / (sin_theta_h * alpha);
  };
  const int steps = 1024;
  for (double edge : {-1.0, 1.0}) {
    for (int i = 0; i < steps; ++i) {
      double a = length * i / steps, b = length * (i + 1) / steps;
      bool below_a = x(a) < edge;
      if (below_a == (x(b) < edge)) continue;
      for (int k = 0; k < 80 && b - a > 1e-6; ++k) {
        double m = 0.5 * (a + b);
        ((x(m) < edge) == below_a ? a : b) = m;
      }
      cuts->push_back(0.5 * (a + b));
    }
  }
}

}  // namespace

SingleScattering ComputeSingleScattering(const Medium& medium, double r, double mu, double mu_s,
                                         double nu, double length, double rel_tol) {
  const AtmosphereParameters& atmosphere = medium.atmosphere();
  const double bottom = medium.bottom_radius();
  RayColumns view;
  view.Build(medium, Accuracy::kReference, r, mu, length);
  std::vector<double> cuts = view.cuts();
  AddPenumbraEdges(medium, r, mu, mu_s, nu, length, &cuts);
  std::sort(cuts.begin(), cuts.end());

  auto integrand = [&](double s) {
    Values<6> out{};
    double r_p = RadiusAt(r, mu, s);
    double mu_s_p = ClampCosine((r * mu_s + s * nu) / r_p);
    Spectrum t_sun = SunDiscTransmittance(medium, Accuracy::kReference, r_p, mu_s_p);
    if (t_sun == Spectrum{}) return out;
    Spectrum t_view = medium.Transmittance(view.ColumnTo(s));
    Densities d = medium.At(r_p - bottom);
    for (int c = 0; c < 3; ++c) {
      double light = t_view[c] * t_sun[c] * atmosphere.solar_irradiance[c];
      out[c] = light * atmosphere.rayleigh_scattering[c] * d.rayleigh;
      out[3 + c] = light * atmosphere.mie_scattering[c] * d.mie;
    }
    return out;
  };
  Values<6> v = IntegrateAdaptive<6>(integrand, cuts, rel_tol);
  return {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
}

}  // namespace aerial::reference
