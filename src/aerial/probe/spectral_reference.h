#pragma once
// The CPU reference in colour: ProbeReference at every wavelength of a spectral sampling (the
// atmosphere extended as the spectral precompute extends it, SpectralAtmosphere), converted to
// linear sRGB by that sampling's conversion. It shares no code with the shaders. At
// SpectralSampling::Midpoint(48) it is the truth the tables' colour is measured against; at the
// tables' own sampling it shares their wavelengths and conversion, and measures the rest.
#include <optional>
#include <vector>

#include "aerial/probe.h"
#include "aerial/spectrum/spectral_sampling.h"

namespace aerial {

// Radiances and irradiances are converted linearly; the two transmittances as the spectral
// transmittance table is, weighted by sunlight (LinearSrgb(E * T) / LinearSrgb(E)); standard errors
// propagate through the conversion's weights as independent errors. at_wavelengths (may be null)
// receives the unconverted results, one per group of three wavelengths (SpectralSampling::Group).
ProbeResult ProbeReferenceSpectral(const AtmosphereParameters& atmosphere, const RayParameters& ray,
                                   std::optional<double> distance_m,
                                   const spectrum::SpectralSampling& sampling,
                                   const ReferenceOptions& options = {},
                                   std::vector<ProbeResult>* at_wavelengths = nullptr);

}  // namespace aerial
