#pragma once
// The spectral precompute (Bruneton 2017, "precomputed luminance"): the radiance tables are
// precomputed in groups of three wavelengths (SpectralAtmosphere::At), each group in float32, and
// folded into linear sRGB by the CIE 1931 observer (SpectralSampling::WavelengthToLinearSrgb).
// Single scattering is computed at every wavelength, the orders >= 2 at every other one and read
// between them (spectrum/higher_orders.h): half the groups stop after single scattering, which is
// a fifth of a precompute. Scattering, Mie, J_ms and the ground irradiance are linear in the
// spectrum, so their colour is exact up to the sampling of the spectrum (values that fall outside
// sRGB's gamut are clamped to 0). Transmittance is not linear in the spectrum: its table is
// computed from LinearSrgbAtmosphere's coefficients, the sunlight-weighted mean extinction per
// channel, exact for thin air and additive along a ray as the lookups that divide two of its
// values need. A table converted from the spectral transmittance instead (LinearSrgb(E T) /
// LinearSrgb(E)) made the sun exact at every elevation but is not additive: dividing two of its
// values near the horizon took 40% of the blue out of a band of the ground at noon. Where sunlight
// crosses the air at render time, it is summed wavelength by wavelength from the channels' optical
// depths (spectrum/spectral_sunlight.h). docs/colour.md measures all three.
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

// The number of three-wavelength precomputes, of them those with all the orders of `options` (the
// others compute single scattering only), and their options (float32, rgb).
int SpectralGroupCount(const PrecomputeOptions& options);
int SpectralAllOrderGroupCount(const PrecomputeOptions& options);
PrecomputeOptions SpectralGroupOptions(const PrecomputeOptions& options, bool all_orders);

// What PrecomputeSpectral allocates besides the tables, by table: each group's tables and
// precompute scratch (device memory), their read-backs and float copies, the colour sums, the
// orders >= 2 kept at every wavelength that has them (spectral_wavelengths / 2 of them, 4 bytes a
// texel each) and what the driver keeps per group, so the estimate grows with --wavelengths as
// the run does.
TableBytes SpectralPrecomputeScratchMemory(const PrecomputeOptions& options);

// Fills spectral `tables` (options().colour == kSpectral); leaves `progress` unfinished.
std::vector<vk::PassTime> PrecomputeSpectral(AtmosphereTables& tables, Progress* progress);

}  // namespace aerial
