#include "aerial/probe/spectral_reference.h"

#include <cmath>

#include "aerial/spectrum/linear_srgb_sum.h"
#include "aerial/spectrum/spectral_atmosphere.h"

namespace aerial {
namespace {

using spectrum::LinearSrgbSum;
using spectrum::Matrix3;

Spectrum Times(const Spectrum& a, const Spectrum& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }
Spectrum Over(const Spectrum& a, const Spectrum& b) { return {a[0] / b[0], a[1] / b[1], a[2] / b[2]}; }

}  // namespace

Spectrum LinearSrgbStdError(const reference::GroupEstimates& estimate, const spectrum::SpectralSampling& sampling,
                            const reference::Channels* scale) {
  Spectrum std_error{};
  for (int o = 0; o < 3; ++o) {
    reference::Channels weights(3 * sampling.groups());
    for (int g = 0; g < sampling.groups(); ++g) {
      const Matrix3 m = sampling.GroupToLinearSrgb(g);
      for (int k = 0; k < 3; ++k) weights[3 * g + k] = m[o][k] * (scale ? (*scale)[3 * g + k] : 1.0);
    }
    std_error[o] = estimate.StdError(weights);
  }
  return std_error;
}

ProbeResult ProbeReferenceSpectral(const AtmosphereParameters& atmosphere, const RayParameters& ray,
                                   std::optional<double> distance_m,
                                   const spectrum::SpectralSampling& sampling, const ReferenceOptions& options,
                                   std::vector<ProbeResult>* at_wavelengths) {
  const spectrum::SpectralAtmosphere spectral(atmosphere);
  LinearSrgbSum sky, irradiance, to_point, sun_irradiance, solar_radiance, sun, sunlit, sunlit_to_point;
  const std::vector<AtmosphereParameters> groups = spectral.AtGroups(sampling);
  const GroupProbe probe = ProbeReferenceGroups(reference::ReferenceGroups(groups), ray, distance_m, options);
  if (at_wavelengths) *at_wavelengths = probe.groups;
  for (int g = 0; g < sampling.groups(); ++g) {
    const AtmosphereParameters& group = groups[size_t(g)];
    const ProbeResult& r = probe.groups[size_t(g)];
    const Matrix3 m = sampling.GroupToLinearSrgb(g);
    sky.Add(m, r.sky_radiance);
    irradiance.Add(m, r.sky_irradiance);
    to_point.Add(m, r.radiance_to_point);
    sun_irradiance.Add(m, r.sun_irradiance);
    solar_radiance.Add(m, r.solar_radiance);
    sun.Add(m, group.solar_irradiance);
    sunlit.Add(m, Times(group.solar_irradiance, r.transmittance));
    sunlit_to_point.Add(m, Times(group.solar_irradiance, r.transmittance_to_point));
  }
  ProbeResult result{};
  result.sky_radiance = sky.value;
  result.sky_radiance_std_error = LinearSrgbStdError(probe.sky_radiance, sampling);
  result.sky_irradiance = irradiance.value;
  result.sky_irradiance_std_error = LinearSrgbStdError(probe.sky_irradiance, sampling);
  result.sun_irradiance = sun_irradiance.value;
  result.solar_radiance = solar_radiance.value;
  result.transmittance = Over(sunlit.value, sun.value);
  if (distance_m) {
    result.radiance_to_point = to_point.value;
    result.radiance_to_point_std_error = LinearSrgbStdError(probe.radiance_to_point, sampling);
    result.transmittance_to_point = Over(sunlit_to_point.value, sun.value);
  }
  return result;
}

}  // namespace aerial
