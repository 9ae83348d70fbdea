#include "aerial/validation/lambertian_radiance.h"

#include <algorithm>
#include <numbers>

#include "aerial/reference/solar_disc.h"

namespace aerial::validation {

reference::GroupEstimates LambertianRadiance(const reference::ReferenceGroups& model,
                                                    const LambertianSurface& surface,
                                                    const std::vector<Spectrum>& albedos, const glm::dvec3& sun,
                                                    int orders, const reference::MonteCarloOptions& monte_carlo) {
  const reference::Medium& medium = model[0].medium();
  double r = std::max(glm::length(surface.point), medium.bottom_radius());
  glm::dvec3 up = glm::normalize(surface.point);
  double mu_s = std::clamp(glm::dot(up, sun), -1.0, 1.0);
  double mu_n = std::clamp(glm::dot(up, surface.normal), -1.0, 1.0);
  double nu_n = std::clamp(glm::dot(surface.normal, sun), -1.0, 1.0);
  reference::GroupEstimates radiance = model.ComputeTiltedSkyIrradiance(r, mu_s, mu_n, nu_n, orders, monte_carlo);
  for (int g = 0; g < model.size(); ++g) {
    const reference::Medium& group = model[g].medium();
    Spectrum sun_transmittance = reference::SunDiscTransmittance(group, reference::Accuracy::kReference, r, mu_s);
    reference::Estimate& e = radiance.groups[size_t(g)];
    for (int c = 0; c < 3; ++c) {
      double direct = group.atmosphere().solar_irradiance[c] * sun_transmittance[c] * std::max(nu_n, 0.0);
      double reflectance = albedos[size_t(g)][c] / std::numbers::pi;
      e.value[c] = reflectance * (direct + e.value[c]);
      e.std_error[c] *= reflectance;
      for (reference::Channels& chunk : radiance.chunk_means) chunk[3 * g + c] *= reflectance;
    }
  }
  return radiance;
}

reference::Estimate LambertianRadiance(const reference::Reference& model, const LambertianSurface& surface,
                                       const glm::dvec3& sun, int orders,
                                       const reference::MonteCarloOptions& monte_carlo) {
  return LambertianRadiance(reference::ReferenceGroups({model.medium().atmosphere()}), surface, {surface.albedo},
                            sun, orders, monte_carlo)
      .groups[0];
}

}  // namespace aerial::validation
