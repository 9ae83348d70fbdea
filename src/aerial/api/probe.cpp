// aerial::Probe and aerial::ProbeReference (include/aerial/probe.h) over ProbeTables and the CPU
// reference.
#include <cmath>
#include <limits>

#include "aerial/api/impl.h"
#include "aerial/probe.h"
#include "aerial/probe/table_probe.h"
#include "aerial/reference/reference.h"

namespace aerial {

std::vector<ProbeResult> Probe(const Tables& tables, std::span<const ProbeQuery> queries) {
  return ProbeTables(ImplOf(tables).tables(), queries);
}

ProbeResult ProbeReference(const AtmosphereParameters& atmosphere, const RayParameters& ray,
                           std::optional<double> distance, const ReferenceOptions& options) {
  static_assert(reference::kChunkPaths == 256 && reference::kAllOrders == std::numeric_limits<int>::max(),
                "ReferenceOptions (aerial/probe.h) documents the chunk size and INT_MAX for all orders");
  const int orders = options.orders;
  const reference::MonteCarloOptions monte_carlo{
      .paths_per_query = options.paths_per_query, .seed = options.seed, .threads = options.threads};
  reference::Reference model(atmosphere);
  ProbeResult result{};
  reference::Estimate sky = model.ComputeRadiance(ray.r, ray.mu, ray.mu_s, ray.nu, orders, INFINITY, monte_carlo);
  result.sky_radiance = sky.value;
  result.sky_radiance_std_error = sky.std_error;
  result.transmittance = model.TransmittanceToBoundary(ray.r, ray.mu);
  result.sun_irradiance = model.ComputeDirectIrradiance(ray.r, ray.mu_s);
  reference::Estimate irradiance = model.ComputeSkyIrradiance(ray.r, ray.mu_s, orders, monte_carlo);
  result.sky_irradiance = irradiance.value;
  result.sky_irradiance_std_error = irradiance.std_error;
  double alpha = atmosphere.sun_angular_radius_rad;
  for (int i = 0; i < 3; ++i)
    result.solar_radiance[i] = atmosphere.solar_irradiance[i] / (M_PI * alpha * alpha);
  if (distance) {
    reference::Estimate to_point = model.ComputeRadiance(ray.r, ray.mu, ray.mu_s, ray.nu, orders, *distance, monte_carlo);
    result.radiance_to_point = to_point.value;
    result.radiance_to_point_std_error = to_point.std_error;
    result.transmittance_to_point = model.Transmittance(ray.r, ray.mu, *distance);
  }
  return result;
}

}  // namespace aerial
