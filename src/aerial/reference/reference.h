#pragma once
// aerial::reference: an independent double-precision CPU reference for the precomputed tables.
// It shares no code with the shaders and uses no tables: transmittance and single scattering are
// direct deterministic quadratures along rays (optical_depth.h, single_scattering.h), higher
// orders and the sky irradiance are path traced (path_tracer.h) with standard errors. The sun is
// a disc, each part of it seen through its own slant of the atmosphere (solar_disc.h).
//
// Conventions (docs/design.md, "Conventions"): r is the distance to the planet centre in meters, mu the
// cosine of the view zenith angle, mu_s of the sun zenith angle, nu of the view-sun angle. nu is
// clamped to the range mu and mu_s allow. Inputs out of range throw aerial::Error; r may exceed
// [bottom, top] by rounding (1 mm) and is then clamped.
#include <cmath>
#include <cstdint>

#include "aerial/atmosphere.h"
#include "aerial/reference/medium.h"
#include "aerial/reference/monte_carlo.h"
#include "aerial/reference/single_scattering.h"

namespace aerial::reference {

class Reference {
 public:
  explicit Reference(const AtmosphereParameters& atmosphere);

  // Distance along the ray to the ground (if hit) or the top of the atmosphere.
  double DistanceToBoundary(double r, double mu) const;
  bool RayIntersectsGround(double r, double mu) const;
  // Over the first distance_m of the ray (clamped to DistanceToBoundary).
  Spectrum Transmittance(double r, double mu, double distance_m) const;
  Spectrum TransmittanceToBoundary(double r, double mu) const;
  // Single scattering over the first distance_m of the ray (infinity: to the boundary).
  SingleScattering ComputeSingleScattering(double r, double mu, double mu_s, double nu,
                                           double distance_m = INFINITY) const;
  // Sum of orders 1..orders with phase functions, over the first distance_m of the view ray;
  // orders = kAllOrders: the whole series (Russian roulette ends the paths). Order 1 is
  // deterministic (ComputeSingleScattering); std_error covers orders >= 2.
  Estimate ComputeRadiance(double r, double mu, double mu_s, double nu, int orders,
                           double distance_m = INFINITY, const MonteCarloOptions& = {}) const;
  // Horizontal surface at radius r.
  Spectrum ComputeDirectIrradiance(double r, double mu_s) const;
  // Sum of sky irradiance orders 1..orders (or kAllOrders) on a horizontal surface at radius r.
  Estimate ComputeSkyIrradiance(double r, double mu_s, int orders, const MonteCarloOptions& = {}) const;
  // The same on a tilted surface whose unit normal n has mu_n = n . up and nu_n = n . sun (nu_n is
  // clamped to the range mu_n and mu_s allow): the hemisphere about n, its part below the horizon
  // seeing the lit ground through the air (irradiance.h).
  Estimate ComputeTiltedSkyIrradiance(double r, double mu_s, double mu_n, double nu_n, int orders,
                                      const MonteCarloOptions& = {}) const;
  static double RayleighPhase(double nu);
  double MiePhase(double nu) const;

  const Medium& medium() const { return medium_; }

 private:
  double CheckRadius(double r) const;
  Medium medium_;
};

}  // namespace aerial::reference
