#pragma once
// Runs the precomputation passes on the GPU (Bruneton & Neyret 2008, Algorithm 4.1), with the
// scattering density split in two passes (incident radiance per (r, mu_s), then its convolution
// with the phase functions per texel). Each pass is timed with GPU timestamps.
#include <functional>
#include <vector>

#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/vk/gpu_timer.h"

namespace aerial {

class Progress;

// Fills `tables`, in either colour mode. Returns the GPU time of every pass, in order. `progress`
// may be null.
std::vector<vk::PassTime> Precompute(AtmosphereTables& tables, Progress* progress);

// Fills `tables` with radiance at the three wavelengths of tables.uniforms() (the rgb mode, and each
// group of the spectral one); leaves `progress` unfinished. With orders > 1, calls
// `after_single_scattering` (if given) when float32 tables hold single scattering and the ground
// irradiance it gives, as tables of orders = 1 would: the spectral mode reads them there.
std::vector<vk::PassTime> PrecomputeRadiance(AtmosphereTables& tables, Progress* progress,
                                             const std::function<void()>& after_single_scattering = {});

// Only the transmittance table T(r, mu), from tables.uniforms().
vk::PassTime ComputeTransmittance(AtmosphereTables& tables);

// Number of passes Precompute runs for these options (progress bars size themselves with it).
int PrecomputePassCount(const PrecomputeOptions& options);

// The sun band's size (transmittance.glsl): 256 elevations over the 10 degrees above each horizon
// where the disc's average differs from its centre's value (0.04 degrees, 0.15 disc radii,
// apart), on the transmittance table's rows. A scratch table of the precomputation.
::vk::Extent3D SunBandExtent(const PrecomputeOptions& options);

}  // namespace aerial
