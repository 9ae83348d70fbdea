#pragma once
// What `aerial probe` prints, as values: the tables' render-time lookups (the same GLSL the frame
// uses, shaders/probe/probe.comp) for a batch of view rays, evaluated on the device.
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

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

// What ProbeReference computes and how finely. Single scattering is a deterministic quadrature;
// the orders above it are path traced in chunks of 256 paths, chunk c drawing from its own random
// stream (seed, c), so a result depends on the seed and the path count, never on the threads.
struct ReferenceOptions {
  int orders = std::numeric_limits<int>::max();  // scattering orders 1..orders (INT_MAX: all); >= 1
  // Paths per Monte Carlo estimate (sky radiance, sky irradiance, radiance to the point), rounded
  // up to a multiple of 256, at least 512; the standard errors fall as 1 / sqrt(paths). The
  // default's is at most ~0.15 % of the radiance of orders 1..4 at daylight points.
  int paths_per_query = 131072;
  uint64_t seed = 1;
  int threads = 0;  // 0: std::thread::hardware_concurrency()
};

// The same quantities from aerial's CPU reference in double precision, which shares no code with
// the shaders and reads no table (`aerial probe --reference`). radiance_to_point and
// transmittance_to_point only with a distance; rayleigh and mie stay 0. Seconds per call, not a
// per-frame function. Throws aerial::Error naming the field for a bad ray, distance or option.
ProbeResult ProbeReference(const AtmosphereParameters& atmosphere, const RayParameters& ray,
                           std::optional<double> distance_m, const ReferenceOptions& options = {});

}  // namespace aerial
