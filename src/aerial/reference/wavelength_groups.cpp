#include "aerial/reference/wavelength_groups.h"

#include <algorithm>
#include <cmath>

#include "aerial/error.h"

namespace aerial::reference {
namespace {

constexpr const char* kWhere = "aerial::reference";

// What every group must share: the atmosphere without its per-wavelength values.
uint64_t GeometryHash(AtmosphereParameters a) {
  for (Spectrum* s : {&a.wavelengths_nm, &a.solar_irradiance, &a.rayleigh_scattering, &a.mie_scattering,
                      &a.mie_extinction, &a.absorption_extinction, &a.ground_albedo})
    *s = {};
  return a.Hash();
}

const std::vector<AtmosphereParameters>& CheckGroups(const std::vector<AtmosphereParameters>& groups) {
  if (groups.empty() || groups.size() > size_t(kMaxWavelengthGroups))
    throw Error("groups", std::to_string(groups.size()), "1 to " + std::to_string(kMaxWavelengthGroups), kWhere);
  for (size_t g = 1; g < groups.size(); ++g)
    if (GeometryHash(groups[g]) != GeometryHash(groups[0]))
      throw Error("groups[" + std::to_string(g) + "]", groups[g].name,
                  "the radii, density profiles, phase function and sun disc of groups[0]", kWhere);
  return groups;
}

// The sampling medium: group 0 with three channels spread over all groups' wavelengths, the
// first, the middle and the last (one group: the group itself).
AtmosphereParameters SamplingAtmosphere(const std::vector<AtmosphereParameters>& groups) {
  AtmosphereParameters sampling = groups[0];
  const int channels = 3 * int(groups.size());
  const std::array<int, 3> picked =
      groups.size() == 1 ? std::array<int, 3>{0, 1, 2} : std::array<int, 3>{0, channels / 2, channels - 1};
  for (int i = 0; i < 3; ++i) {
    const int c = picked[size_t(i)];
    const AtmosphereParameters& g = groups[size_t(c / 3)];
    const size_t k = size_t(c % 3);
    sampling.wavelengths_nm[size_t(i)] = g.wavelengths_nm[k];
    sampling.solar_irradiance[size_t(i)] = g.solar_irradiance[k];
    sampling.rayleigh_scattering[size_t(i)] = g.rayleigh_scattering[k];
    sampling.mie_scattering[size_t(i)] = g.mie_scattering[k];
    sampling.mie_extinction[size_t(i)] = g.mie_extinction[k];
    sampling.absorption_extinction[size_t(i)] = g.absorption_extinction[k];
    sampling.ground_albedo[size_t(i)] = g.ground_albedo[k];
  }
  return sampling;
}

}  // namespace

Channels::Channels(int size, double value) : size_(size) { values_.fill(value); }

double Channels::Max() const {
  double m = 0.0;
  for (int c = 0; c < size_; ++c) m = std::max(m, values_[size_t(c)]);
  return m;
}

WavelengthGroups::WavelengthGroups(const AtmosphereParameters& atmosphere)
    : WavelengthGroups(std::vector<AtmosphereParameters>{atmosphere}) {}

WavelengthGroups::WavelengthGroups(const std::vector<AtmosphereParameters>& groups)
    : sampling_(SamplingAtmosphere(CheckGroups(groups))), channels_(3 * int(groups.size())) {
  for (Channels* values : {&rayleigh_scattering_, &mie_scattering_, &mie_extinction_, &absorption_extinction_,
                           &solar_irradiance_, &ground_albedo_})
    *values = Channels(channels_);
  for (int c = 0; c < channels_; ++c) {
    const AtmosphereParameters& g = groups[size_t(c / 3)];
    const size_t k = size_t(c % 3);
    rayleigh_scattering_[c] = g.rayleigh_scattering[k];
    mie_scattering_[c] = g.mie_scattering[k];
    mie_extinction_[c] = g.mie_extinction[k];
    absorption_extinction_[c] = g.absorption_extinction[k];
    solar_irradiance_[c] = g.solar_irradiance[k];
    ground_albedo_[c] = g.ground_albedo[k];
  }
}

Channels WavelengthGroups::OpticalDepth(const Column& column) const {
  Channels tau(channels_);
  for (int c = 0; c < channels_; ++c)
    tau[c] = rayleigh_scattering_[c] * column.rayleigh + mie_extinction_[c] * column.mie +
             absorption_extinction_[c] * column.absorption;
  return tau;
}

Channels WavelengthGroups::Transmittance(const Column& column) const {
  Channels t = OpticalDepth(column);
  for (int c = 0; c < channels_; ++c) t[c] = std::exp(-t[c]);
  return t;
}

}  // namespace aerial::reference
