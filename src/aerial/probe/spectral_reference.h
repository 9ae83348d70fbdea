#pragma once
// The CPU reference in colour: ProbeReference at every wavelength of a spectral sampling (the
// atmosphere extended as the spectral precompute extends it, SpectralAtmosphere), converted to
// linear sRGB by that sampling's conversion. It shares no code with the shaders. At
// SpectralSampling::Midpoint(48) it is the truth the tables' colour is measured against; at the
// tables' own sampling it shares their wavelengths and conversion, and measures the rest.
#include <optional>
#include <vector>

#include "aerial/probe.h"
#include "aerial/reference/reference.h"
#include "aerial/spectrum/spectral_sampling.h"

namespace aerial {

// ProbeReference at every group of `model`, the Monte Carlo estimates of all groups from the same
// paths (reference/wavelength_groups.h): the sky radiance, sky irradiance and radiance to the point
// of every group with their chunks, which give the errors of sums over groups.
struct GroupProbe {
  std::vector<ProbeResult> groups;
  reference::GroupEstimates sky_radiance, sky_irradiance, radiance_to_point;
};
GroupProbe ProbeReferenceGroups(const reference::ReferenceGroups& model, const RayParameters& ray,
                                std::optional<double> distance_m, const ReferenceOptions& options);

// The standard error of the linear sRGB of a spectrum given at the wavelengths of `sampling` (its
// groups' values, sum_g GroupToLinearSrgb(g) X_g), X estimated by `estimate` with each channel
// scaled by scale[c] (null: 1). The groups' errors are correlated, so it is taken from the chunks.
Spectrum LinearSrgbStdError(const reference::GroupEstimates& estimate, const spectrum::SpectralSampling& sampling,
                            const reference::Channels* scale = nullptr);

// Radiances and irradiances are converted linearly; the two transmittances as the spectral
// transmittance table is, weighted by sunlight (LinearSrgb(E * T) / LinearSrgb(E)); standard errors
// are the converted values' own (LinearSrgbStdError). at_wavelengths (may be null)
// receives the unconverted results, one per group of three wavelengths (SpectralSampling::Group).
ProbeResult ProbeReferenceSpectral(const AtmosphereParameters& atmosphere, const RayParameters& ray,
                                   std::optional<double> distance_m,
                                   const spectrum::SpectralSampling& sampling,
                                   const ReferenceOptions& options = {},
                                   std::vector<ProbeResult>* at_wavelengths = nullptr);

}  // namespace aerial
