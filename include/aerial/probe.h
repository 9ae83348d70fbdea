#pragma once
// What `aerial probe` prints, as values: the tables' render-time lookups (the same GLSL the frame
// uses, shaders/probe/probe.comp) for a batch of view rays, evaluated on the device.
#include <optional>
#include <span>
#include <vector>

#include "aerial/reference/monte_carlo.h"
#include "aerial/tables.h"
#include "aerial/view_geometry.h"

namespace aerial {

struct ProbeQuery {
  RayParameters ray;
  double distance_m = 0.0;  // for radiance_to_point and transmittance_to_point
};

// Radiances in W/m^2/sr/nm, irradiances in W/m^2/nm, per wavelength.
struct ProbeResult {
  Spectrum sky_radiance, transmittance, sun_irradiance, sky_irradiance, solar_radiance;
  Spectrum radiance_to_point, transmittance_to_point;
  Spectrum rayleigh, mie;  // raw table values without phase, along the whole ray
  // The reference's Monte Carlo standard errors of the three radiances above (0 for the tables).
  Spectrum sky_radiance_std_error, sky_irradiance_std_error, radiance_to_point_std_error;
};

// One result per query, in order. Waits for the device (it is not a per-frame call).
std::vector<ProbeResult> Probe(const Tables& tables, std::span<const ProbeQuery> queries);

// The same quantities from aerial's CPU reference in double precision (quadrature for single
// scattering, Monte Carlo for the orders above it; `aerial probe --reference`), for scattering
// orders 1..orders (INT_MAX: all of them). radiance_to_point and transmittance_to_point only
// with a distance; rayleigh and mie stay 0. Seconds per call, not a per-frame function.
ProbeResult ProbeReference(const AtmosphereParameters& atmosphere, const RayParameters& ray,
                           std::optional<double> distance_m, int orders,
                           const reference::MonteCarloOptions& monte_carlo = {});

}  // namespace aerial
