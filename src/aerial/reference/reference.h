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
#include <span>
#include <vector>

#include "aerial/atmosphere.h"
#include "aerial/reference/medium.h"
#include "aerial/reference/monte_carlo.h"
#include "aerial/reference/single_scattering.h"
#include "aerial/reference/wavelength_groups.h"

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

  const Medium& medium() const { return wavelengths_.sampling(); }

 private:
  friend class ReferenceGroups;
  double CheckRadius(double r) const;
  // ComputeRadiance and ComputeTiltedSkyIrradiance of every group of `wavelengths`, `groups` their
  // References (this one's checks apply to all: they share the geometry).
  GroupEstimates RadianceOfGroups(std::span<const Reference> groups, const WavelengthGroups& wavelengths, double r,
                                  double mu, double mu_s, double nu, int orders, double distance_m,
                                  const MonteCarloOptions& options) const;
  GroupEstimates TiltedSkyIrradianceOfGroups(const WavelengthGroups& wavelengths, double r, double mu_s, double mu_n,
                                             double nu_n, int orders, const MonteCarloOptions& options) const;
  WavelengthGroups wavelengths_;  // the one group, for the Monte Carlo estimates
};

// One atmosphere at several groups of three wavelengths (a spectral reference): each group's
// Reference, and the Monte Carlo estimates of every group from one set of paths
// (wavelength_groups.h), at about the cost of one group's.
class ReferenceGroups {
 public:
  // The groups must share the radii, density profiles, phase function and sun disc.
  explicit ReferenceGroups(const std::vector<AtmosphereParameters>& groups);

  int size() const { return int(groups_.size()); }
  const Reference& operator[](int g) const { return groups_[size_t(g)]; }

  // Reference::ComputeRadiance, ComputeSkyIrradiance and ComputeTiltedSkyIrradiance of every group
  // (monte_carlo.h: GroupEstimates, whose chunks give the errors of sums over groups).
  GroupEstimates ComputeRadiance(double r, double mu, double mu_s, double nu, int orders,
                                 double distance_m = INFINITY, const MonteCarloOptions& = {}) const;
  GroupEstimates ComputeSkyIrradiance(double r, double mu_s, int orders, const MonteCarloOptions& = {}) const;
  GroupEstimates ComputeTiltedSkyIrradiance(double r, double mu_s, double mu_n, double nu_n, int orders,
                                            const MonteCarloOptions& = {}) const;

 private:
  std::vector<Reference> groups_;
  WavelengthGroups wavelengths_;
};

}  // namespace aerial::reference
