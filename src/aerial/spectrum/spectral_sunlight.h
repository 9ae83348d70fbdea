#pragma once
// The sunlight a path lets through, in the colour channels of spectral tables
// (docs/colour.md, "Transmittance").
//
// Spectral tables keep one three-channel transmittance, computed from each constituent's
// sunlight-weighted coefficient per channel (LinearSrgbAtmosphere). A colour's transmittance is
// not the exponential of a colour's optical depth: each wavelength is attenuated by its own, and
// along 10 km of air near the ground the product of three channels' transmittances is off by
// 1-1.5% in luminance, at the low sun by 0.01-0.015 in u'v'. But every wavelength's optical depth
// is a linear function of the three channels' optical depths: each is a sum over the same three
// constituents (Rayleigh, Mie, ozone), tau_c = sum_k A_ck N_k with N_k a constituent's column
// density along the path, so tau(lambda) = sigma(lambda) . N = g(lambda) . tau_rgb with
// g = A^-T sigma(lambda). The sunlight after the path is then summed over the precompute's
// wavelengths, as the CPU reference sums it:
//   light_c = sum_j w_jc exp(-g_j . tau_rgb),
// with w_jc wavelength j's share of channel c of LinearSrgb(E beta) for the scattering coefficient
// beta of Rayleigh, of Mie, or 1 for the direct sunlight. At tau = 0 each channel's shares sum to 1,
// so in thin air this is the three-channel transmittance's value.
#include <vector>

#include "aerial/spectrum/spectral_atmosphere.h"
#include "aerial/spectrum/spectral_sampling.h"

namespace aerial::spectrum {

struct SpectralSunlight {
  std::vector<Spectrum> exponents;  // g_j
  std::vector<Spectrum> rayleigh_shares, mie_shares, direct_shares;  // w_jc
};

// The terms for the render-time atmosphere `linear_srgb` (LinearSrgbAtmosphere of the same
// atmosphere and sampling). Empty where the constituents' three-channel coefficients do not
// determine their column densities (two constituents with the same spectrum, which leaves the
// product of the channels' transmittances the best this can do).
SpectralSunlight MakeSpectralSunlight(const SpectralAtmosphere& atmosphere,
                                      const AtmosphereParameters& linear_srgb,
                                      const SpectralSampling& sampling);

// light_c above for the channels' optical depths tau_rgb, with one of the share sets.
Spectrum PathSunlight(const SpectralSunlight& sunlight, const std::vector<Spectrum>& shares,
                      const Spectrum& channel_optical_depth);

}  // namespace aerial::spectrum
