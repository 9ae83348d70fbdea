#pragma once
// The atmosphere as a participating medium: the densities of its three species (Rayleigh, Mie,
// absorbing ozone) at an altitude, their coefficients, and the altitude levels at which rays are
// cut into pieces smooth enough for Gauss-Legendre quadrature.
#include <algorithm>
#include <cmath>
#include <vector>

#include "aerial/atmosphere.h"

namespace aerial::reference {

// Profile densities (dimensionless, in [0, 1]) at one altitude.
struct Densities {
  double rayleigh = 0.0, mie = 0.0, absorption = 0.0;
};

// Column densities, the integrals of Densities along a path, in meters.
struct Column {
  double rayleigh = 0.0, mie = 0.0, absorption = 0.0;
};
inline Column operator+(const Column& a, const Column& b) {
  return {a.rayleigh + b.rayleigh, a.mie + b.mie, a.absorption + b.absorption};
}

// How finely rays are cut (see Medium::level_radii).
enum class Accuracy {
  kReference,   // deterministic results: ~1e-15 relative quadrature error.
  kMonteCarlo,  // path tracer: <1e-4 relative, far below its noise, at a quarter of the cost.
};

// DensityProfile::Density (parameters.cpp) inlined for the quadrature's inner loop: the same
// clamp(exp_term exp(exp_scale h) + linear h + constant, 0, 1), skipping exp() when exp_term = 0.
// medium_test checks they agree.
inline double ProfileDensity(const DensityProfile& profile, double altitude_m) {
  const DensityProfileLayer& layer =
      altitude_m < profile.layers[0].width_m ? profile.layers[0] : profile.layers[1];
  double density = layer.linear_term_per_m * altitude_m + layer.constant_term;
  if (layer.exp_term != 0.0) density += layer.exp_term * std::exp(layer.exp_scale_per_m * altitude_m);
  return std::clamp(density, 0.0, 1.0);
}

class Medium {
 public:
  explicit Medium(const AtmosphereParameters& atmosphere);

  const AtmosphereParameters& atmosphere() const { return atmosphere_; }
  double bottom_radius() const { return atmosphere_.bottom_radius_m; }
  double top_radius() const { return atmosphere_.top_radius_m; }

  // Rounding puts ray ends on the ground at altitudes like -1e-9 m, where a profile with
  // layers[0].width_m = 0 would switch to its (zero) lower layer: altitudes are clamped at 0.
  Densities At(double altitude_m) const {
    altitude_m = std::max(altitude_m, 0.0);
    return {ProfileDensity(atmosphere_.rayleigh_density, altitude_m),
            ProfileDensity(atmosphere_.mie_density, altitude_m),
            ProfileDensity(atmosphere_.absorption_density, altitude_m)};
  }

  // tau = beta_R C_R + beta_M,ext C_M + beta_O C_O per wavelength, and T = exp(-tau).
  Spectrum OpticalDepth(const Column& column) const;
  Spectrum Transmittance(const Column& column) const;

  // Wavelength-averaged optical depth, for importance-sampling heuristics.
  double MeanOpticalDepth(const Column& c) const {
    return mean_rayleigh_ * c.rayleigh + mean_mie_extinction_ * c.mie +
           mean_absorption_ * c.absorption;
  }

  // Sorted radii, from bottom to top, that cut any ray into pieces on which every density is
  // smooth: the profiles' kinks (layer boundaries, clamps to 0 or 1) and, for exponential terms,
  // a level every 2 (kReference) or 4 (kMonteCarlo) scale heights. On a piece where exp(-h/H)
  // varies by e^2a, n-point Gauss-Legendre errs relatively by ~a^2n 2^(2n+1) (n!)^4 /
  // ((2n+1) ((2n)!)^3) (Abramowitz & Stegun 25.4.30): 2e-18 for kReference (a = 1, n = 8) and
  // 8e-5 for kMonteCarlo (a = 2, n = 4; 4e-5 measured on Earth rays). kMonteCarlo also stops
  // refining an exponential term above the altitude where its species' extinction stays under
  // 1e-6 of the medium's (on Earth, Mie above about 19 km).
  const std::vector<double>& level_radii(Accuracy accuracy) const {
    return accuracy == Accuracy::kReference ? reference_levels_ : monte_carlo_levels_;
  }

 private:
  AtmosphereParameters atmosphere_;
  double mean_rayleigh_, mean_mie_extinction_, mean_absorption_;
  std::vector<double> reference_levels_, monte_carlo_levels_;
};

}  // namespace aerial::reference
