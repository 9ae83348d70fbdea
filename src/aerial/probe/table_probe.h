#pragma once
// Evaluates the render-time table lookups (shaders/probe/probe.comp) for a batch of view rays.
#include <span>
#include <vector>

#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/probe/view_geometry.h"

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
};

std::vector<ProbeResult> ProbeTables(const AtmosphereTables& tables,
                                     std::span<const ProbeQuery> queries);

}  // namespace aerial
