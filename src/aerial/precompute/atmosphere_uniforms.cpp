#include "aerial/precompute/atmosphere_uniforms.h"

#include <string>

#include "aerial/error.h"
#include "aerial/precompute/sample_counts.h"
#include "aerial/precompute/spectral_precompute.h"
#include "aerial/spectrum/spectral_sunlight.h"

namespace aerial {
namespace {

std::array<float, 4> ToFloat4(const Spectrum& s) {
  return {float(s[0]), float(s[1]), float(s[2]), 0.0f};
}

std::array<GpuDensityLayer, 2> ToGpu(const DensityProfile& profile) {
  std::array<GpuDensityLayer, 2> layers{};
  for (int i = 0; i < 2; ++i) {
    const DensityProfileLayer& l = profile.layers[i];
    layers[i] = {float(l.width_m), float(l.exp_term), float(l.exp_scale_per_m),
                 float(l.linear_term_per_m), float(l.constant_term), 0, 0, 0};
  }
  return layers;
}

void SetSpectralSunlight(const AtmosphereParameters& atmosphere, const AtmosphereParameters& linear_srgb,
                         const PrecomputeOptions& options, AtmosphereUniforms& u) {
  const spectrum::SpectralSunlight sunlight =
      spectrum::MakeSpectralSunlight(spectrum::SpectralAtmosphere(atmosphere), linear_srgb,
                                     spectrum::SpectralSampling::ForTables(options.spectral_wavelengths));
  const int terms = int(sunlight.exponents.size());
  if (terms > kMaxSpectralSunlightTerms) throw Error("wavelengths", std::to_string(terms), "at most 48");
  u.spectral_sunlight_terms = {terms, 1, 0, 0};
  for (int j = 0; j < terms; ++j) {
    u.spectral_sunlight_exponent[j] = ToFloat4(sunlight.exponents[j]);
    u.spectral_sunlight_rayleigh[j] = ToFloat4(sunlight.rayleigh_shares[j]);
    u.spectral_sunlight_mie[j] = ToFloat4(sunlight.mie_shares[j]);
    u.spectral_sunlight_direct[j] = ToFloat4(sunlight.direct_shares[j]);
  }
}

}  // namespace

AtmosphereUniforms MakeAtmosphereUniforms(const AtmosphereParameters& atmosphere,
                                          const PrecomputeOptions& options) {
  const AtmosphereParameters a = ShaderAtmosphere(atmosphere, options);
  const TableResolution& r = options.resolution;
  const SampleCounts s = SampleCountsOf(options);
  AtmosphereUniforms u{};
  u.solar_irradiance = ToFloat4(a.solar_irradiance);
  u.rayleigh_scattering = ToFloat4(a.rayleigh_scattering);
  u.mie_scattering = ToFloat4(a.mie_scattering);
  u.mie_extinction = ToFloat4(a.mie_extinction);
  u.absorption_extinction = ToFloat4(a.absorption_extinction);
  u.ground_albedo = ToFloat4(a.ground_albedo);
  u.rayleigh_density = ToGpu(a.rayleigh_density);
  u.mie_density = ToGpu(a.mie_density);
  u.absorption_density = ToGpu(a.absorption_density);
  u.bottom_radius = float(a.bottom_radius_m);
  u.top_radius = float(a.top_radius_m);
  u.sun_angular_radius = float(a.sun_angular_radius_rad);
  u.mie_phase_g = float(a.mie_phase_g);
  u.mu_s_min = float(a.mu_s_min);
  u.multiple_density_scale = kMultipleDensityScale;
  u.transmittance_size = {r.transmittance_mu, r.transmittance_r, 0, 0};
  u.irradiance_size = {r.irradiance_mu_s, r.irradiance_r, 0, 0};
  u.scattering_size = {r.scattering_r, r.scattering_mu, r.scattering_mu_s, r.scattering_nu};
  u.density_size = {s.density_r, s.density_mu, s.density_mu_s, s.density_nu};
  u.density_directions = {s.density_theta_up, s.density_theta_down, s.density_phi, 0};
  u.sample_counts = {s.transmittance_steps, s.ray_steps, s.irradiance_zenith, s.irradiance_azimuth};
  u.multiple_scattering_steps = {s.multiple_scattering_steps, 0, 0, 0};
  u.multiple_density_size = {r.multiple_density_r, r.multiple_density_mu, r.multiple_density_mu_s,
                             r.multiple_density_nu};
  if (options.colour == ColourMode::kSpectral) SetSpectralSunlight(atmosphere, a, options, u);
  return u;
}

}  // namespace aerial
