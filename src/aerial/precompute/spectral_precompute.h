#pragma once
// The spectral precompute (Bruneton 2017, "precomputed luminance"): the radiance tables are
// precomputed once per group of three wavelengths (SpectralAtmosphere::At), each group in float32,
// and folded into linear sRGB by the CIE 1931 observer (SpectralSampling::GroupToLinearSrgb).
// Scattering, Mie, J_ms and the ground irradiance are linear in the spectrum, so their colour is
// exact up to the sampling of the spectrum. Transmittance is not: the table holds, per channel,
// the sunlight-weighted transmittance LinearSrgb(E * T) / LinearSrgb(E), so that the sun and the
// light it brings are exact and a surface seen through the air is approximated (docs/colour.md
// measures it). The render-time shaders then work in linear sRGB with the coefficients of
// LinearSrgbAtmosphere.
#include <vector>

#include "aerial/atmosphere.h"
#include "aerial/table_options.h"
#include "aerial/vk/gpu_timer.h"

namespace aerial {

class AtmosphereTables;
class Progress;

// The atmosphere the shaders receive for these options: `atmosphere` itself in rgb mode, its
// linear sRGB counterpart in spectral mode.
AtmosphereParameters ShaderAtmosphere(const AtmosphereParameters& atmosphere, const PrecomputeOptions& options);

// The number of three-wavelength precomputes, and their options (float32, rgb).
int SpectralGroupCount(const PrecomputeOptions& options);
PrecomputeOptions SpectralGroupOptions(const PrecomputeOptions& options);

// Fills spectral `tables` (options().colour == kSpectral); leaves `progress` unfinished.
std::vector<vk::PassTime> PrecomputeSpectral(AtmosphereTables& tables, Progress* progress);

}  // namespace aerial
