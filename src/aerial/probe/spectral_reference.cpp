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

ProbeResult ProbeReferenceSpectral(const AtmosphereParameters& atmosphere, const RayParameters& ray,
                                   std::optional<double> distance_m,
                                   const spectrum::SpectralSampling& sampling, const ReferenceOptions& options,
                                   std::vector<ProbeResult>* at_wavelengths) {
  const spectrum::SpectralAtmosphere spectral(atmosphere);
  LinearSrgbSum sky, sky_variance, irradiance, irradiance_variance, to_point, to_point_variance;
  LinearSrgbSum sun_irradiance, solar_radiance, sun, sunlit, sunlit_to_point;
  for (int g = 0; g < sampling.groups(); ++g) {
    AtmosphereParameters group = spectral.At(sampling.Group(g));
    ProbeResult r = ProbeReference(group, ray, distance_m, options);
    if (at_wavelengths) at_wavelengths->push_back(r);
    const Matrix3 m = sampling.GroupToLinearSrgb(g);
    sky.Add(m, r.sky_radiance);
    sky_variance.AddVariance(m, r.sky_radiance_std_error);
    irradiance.Add(m, r.sky_irradiance);
    irradiance_variance.AddVariance(m, r.sky_irradiance_std_error);
    to_point.Add(m, r.radiance_to_point);
    to_point_variance.AddVariance(m, r.radiance_to_point_std_error);
    sun_irradiance.Add(m, r.sun_irradiance);
    solar_radiance.Add(m, r.solar_radiance);
    sun.Add(m, group.solar_irradiance);
    sunlit.Add(m, Times(group.solar_irradiance, r.transmittance));
    sunlit_to_point.Add(m, Times(group.solar_irradiance, r.transmittance_to_point));
  }
  ProbeResult result{};
  result.sky_radiance = sky.value;
  result.sky_radiance_std_error = sky_variance.Sqrt();
  result.sky_irradiance = irradiance.value;
  result.sky_irradiance_std_error = irradiance_variance.Sqrt();
  result.sun_irradiance = sun_irradiance.value;
  result.solar_radiance = solar_radiance.value;
  result.transmittance = Over(sunlit.value, sun.value);
  if (distance_m) {
    result.radiance_to_point = to_point.value;
    result.radiance_to_point_std_error = to_point_variance.Sqrt();
    result.transmittance_to_point = Over(sunlit_to_point.value, sun.value);
  }
  return result;
}

}  // namespace aerial
