#include "aerial/probe/spectral_table_probe.h"

#include "aerial/precompute/spectral_precompute.h"
#include "aerial/spectrum/spectral_atmosphere.h"
#include "aerial/spectrum/spectral_sampling.h"

namespace aerial {

std::vector<ProbeResult> ProbeSpectralTablesAtWavelengths(const Device& device, const AtmosphereParameters& atmosphere,
                                                          const PrecomputeOptions& options, const TableLoadOptions& load,
                                                          const ProbeQuery& query) {
  const spectrum::SpectralSampling sampling = spectrum::SpectralSampling::ForTables(options.spectral_wavelengths);
  const std::vector<AtmosphereParameters> groups = spectrum::SpectralAtmosphere(atmosphere).AtGroups(sampling);
  const PrecomputeOptions group_options = SpectralGroupOptions(options, /*all_orders=*/true);
  std::vector<ProbeResult> results;
  for (const AtmosphereParameters& group : groups) {
    const Tables tables = Tables::LoadOrPrecompute(device, group, group_options, load);
    results.push_back(Probe(tables, std::span(&query, 1)).front());
  }
  return results;
}

}  // namespace aerial
