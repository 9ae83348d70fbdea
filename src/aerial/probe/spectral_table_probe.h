#pragma once
// The spectral tables' spectrum along a ray. Spectral tables hold linear sRGB, folded from
// precomputes at three wavelengths at a time (precompute/spectral_precompute.h); this probes each
// such group's own tables instead: rgb tables (float32, all the orders asked for) of the
// atmosphere at the group's wavelengths (SpectralAtmosphere::At), one group of the tables'
// sampling (SpectralSampling::ForTables) after the other. The spectral precompute computes the
// orders >= 2 at every other wavelength and reads between them; here each wavelength has its own.
// A group's tables are tables like any others, keyed by their atmosphere: cached, so a second
// probe of the same atmosphere and options loads them.
#include <vector>

#include "aerial/probe.h"

namespace aerial {

// One result per group of three wavelengths, in the order of SpectralSampling::Group; options:
// the spectral tables' (colour kSpectral).
std::vector<ProbeResult> ProbeSpectralTablesAtWavelengths(const Device& device, const AtmosphereParameters& atmosphere,
                                                          const PrecomputeOptions& options, const TableLoadOptions& load,
                                                          const ProbeQuery& query);

}  // namespace aerial
