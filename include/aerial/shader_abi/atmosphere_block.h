#pragma once
// The std140 uniform block every shader reads (AtmosphereBlock in shaders/include/definitions.glsl):
// the atmosphere in float, plus table sizes and sample counts. The precompute fills it
// (precompute/atmosphere_uniforms.h); a client's shaders bind it at set 0, binding 0
// (aerial_perspective.glsl). tests/uniform_layout_test.cpp checks it member by member against
// the GLSL compiler's layout.
#include <array>
#include <cstddef>

namespace aerial {

struct alignas(16) GpuDensityLayer {
  float width, exp_term, exp_scale, linear_term, constant_term, pad0, pad1, pad2;
};

// The factor J_ms is stored times (AtmosphereUniforms::multiple_density_scale), 2^20.
inline constexpr float kMultipleDensityScale = 1048576.0f;

// The most wavelengths a spectral precompute runs at (PrecomputeOptions::spectral_wavelengths).
inline constexpr int kMaxSpectralSunlightTerms = 48;

struct alignas(16) AtmosphereUniforms {
  std::array<float, 4> solar_irradiance;
  std::array<float, 4> rayleigh_scattering;
  std::array<float, 4> mie_scattering;
  std::array<float, 4> mie_extinction;
  std::array<float, 4> absorption_extinction;
  std::array<float, 4> ground_albedo;
  std::array<GpuDensityLayer, 2> rayleigh_density;
  std::array<GpuDensityLayer, 2> mie_density;
  std::array<GpuDensityLayer, 2> absorption_density;
  float bottom_radius, top_radius, sun_angular_radius, mie_phase_g;
  // J_ms is stored times this (Tables::multiple_density): a power of two that puts its values,
  // 1e-9 to 1e-6 per metre, in half floats' normal range (from 6.1e-5).
  float mu_s_min, multiple_density_scale, pad1, pad2;
  std::array<int, 4> transmittance_size;
  std::array<int, 4> irradiance_size;
  std::array<int, 4> scattering_size;     // r, mu, mu_s, nu
  std::array<int, 4> density_size;        // r, mu, mu_s, nu
  std::array<int, 4> density_directions;  // theta up, theta down, phi, unused
  std::array<int, 4> sample_counts;       // transmittance, ray, irradiance zenith, azimuth
  std::array<int, 4> multiple_scattering_steps;
  std::array<int, 4> multiple_density_size;  // r, mu, mu_s, nu
  // Spectral tables: the sunlight a path lets through, summed over the precompute's wavelengths
  // (spectrum/spectral_sunlight.h; GetPathSunlight in transmittance.glsl). x: the wavelengths
  // summed, 0 for rgb tables (the path's transmittance is then used as it is); y: 1 where the
  // channels are linear sRGB (spectral tables), 0 where they are wavelengths (rgb).
  std::array<int, 4> spectral_sunlight_terms;
  // Per wavelength j: xyz the weights g_j of its optical depth, tau_j = g_j . channels' optical
  // depths; and its share of each channel of the sunlight that Rayleigh and Mie scatter and of the
  // direct sunlight (each sums to 1 per channel over j).
  std::array<std::array<float, 4>, kMaxSpectralSunlightTerms> spectral_sunlight_exponent;
  std::array<std::array<float, 4>, kMaxSpectralSunlightTerms> spectral_sunlight_rayleigh;
  std::array<std::array<float, 4>, kMaxSpectralSunlightTerms> spectral_sunlight_mie;
  std::array<std::array<float, 4>, kMaxSpectralSunlightTerms> spectral_sunlight_direct;
};
static_assert(offsetof(AtmosphereUniforms, rayleigh_density) == 96);
static_assert(offsetof(AtmosphereUniforms, bottom_radius) == 96 + 3 * 64);
static_assert(offsetof(AtmosphereUniforms, transmittance_size) == 96 + 3 * 64 + 32);
static_assert(sizeof(AtmosphereUniforms) == 96 + 3 * 64 + 32 + 9 * 16 + 4 * kMaxSpectralSunlightTerms * 16);

}  // namespace aerial
