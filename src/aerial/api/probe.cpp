// aerial::Probe and aerial::ProbeReference (include/aerial/probe.h) over ProbeTables and the CPU
// reference.
#include <cmath>
#include <limits>

#include "aerial/api/impl.h"
#include "aerial/probe.h"
#include "aerial/probe/spectral_reference.h"
#include "aerial/probe/table_probe.h"
#include "aerial/reference/reference.h"

namespace aerial {

std::vector<ProbeResult> Probe(const Tables& tables, std::span<const ProbeQuery> queries) {
  return ProbeTables(ImplOf(tables).tables(), queries);
}

GroupProbe ProbeReferenceGroups(const reference::ReferenceGroups& model, const RayParameters& ray,
                                std::optional<double> distance, const ReferenceOptions& options) {
  static_assert(reference::kChunkPaths == 256 && reference::kAllOrders == std::numeric_limits<int>::max(),
                "ReferenceOptions (aerial/probe.h) documents the chunk size and INT_MAX for all orders");
  const int orders = options.orders;
  const reference::MonteCarloOptions monte_carlo{
      .paths_per_query = options.paths_per_query, .seed = options.seed, .threads = options.threads};
  GroupProbe probe;
  probe.sky_radiance = model.ComputeRadiance(ray.r, ray.mu, ray.mu_s, ray.nu, orders, INFINITY, monte_carlo);
  probe.sky_irradiance = model.ComputeSkyIrradiance(ray.r, ray.mu_s, orders, monte_carlo);
  if (distance)
    probe.radiance_to_point = model.ComputeRadiance(ray.r, ray.mu, ray.mu_s, ray.nu, orders, *distance, monte_carlo);
  probe.groups.resize(size_t(model.size()));
  for (int g = 0; g < model.size(); ++g) {
    const reference::Reference& group = model[g];
    const AtmosphereParameters& atmosphere = group.medium().atmosphere();
    ProbeResult& result = probe.groups[size_t(g)];
    const reference::Estimate& sky = probe.sky_radiance.groups[size_t(g)];
    const reference::Estimate& irradiance = probe.sky_irradiance.groups[size_t(g)];
    result.sky_radiance = sky.value;
    result.sky_radiance_std_error = sky.std_error;
    result.transmittance = group.TransmittanceToBoundary(ray.r, ray.mu);
    result.sun_irradiance = group.ComputeDirectIrradiance(ray.r, ray.mu_s);
    result.sky_irradiance = irradiance.value;
    result.sky_irradiance_std_error = irradiance.std_error;
    double alpha = atmosphere.sun_angular_radius_rad;
    for (int i = 0; i < 3; ++i)
      result.solar_radiance[i] = atmosphere.solar_irradiance[i] / (M_PI * alpha * alpha);
    if (distance) {
      const reference::Estimate& to_point = probe.radiance_to_point.groups[size_t(g)];
      result.radiance_to_point = to_point.value;
      result.radiance_to_point_std_error = to_point.std_error;
      result.transmittance_to_point = group.Transmittance(ray.r, ray.mu, *distance);
    }
  }
  return probe;
}

ProbeResult ProbeReference(const AtmosphereParameters& atmosphere, const RayParameters& ray,
                           std::optional<double> distance, const ReferenceOptions& options) {
  return ProbeReferenceGroups(reference::ReferenceGroups({atmosphere}), ray, distance, options).groups[0];
}

}  // namespace aerial
