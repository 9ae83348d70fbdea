#pragma once
// One atmosphere at several groups of three wavelengths (a spectral reference: SpectralAtmosphere's
// groups), traced by one set of Monte Carlo paths. A path's geometry (its vertices, the column
// densities along its segments) does not depend on the wavelength; only its weights do. So each
// path is sampled once, from a sampling medium whose three channels span the groups' spectrum
// (the first, middle and last wavelength), and carries a throughput at every wavelength: the
// weight of channel c is its own f_c / pdf and T_c / pdf, with the pdf the sampling medium's
// (hero wavelength sampling, Wilkie et al. 2014, "Hero Wavelength Spectral Sampling", with the
// sampling channels fixed instead of drawn). Unbiased for every channel: the pdfs are positive
// wherever any channel's integrand is (distance_sampler.h's defensive mixture, the phase lobes'
// full support). With one group the sampling medium is that group's own, and a path is traced
// exactly as a one-group reference traces it.
#include <array>
#include <vector>

#include "aerial/atmosphere.h"
#include "aerial/reference/medium.h"

namespace aerial::reference {

inline constexpr int kMaxWavelengthGroups = 16;  // 48 wavelengths
inline constexpr int kMaxChannels = 3 * kMaxWavelengthGroups;

// Values at every wavelength of a WavelengthGroups: channel 3 g + i is group g's i-th.
class Channels {
 public:
  explicit Channels(int size = 0, double value = 0.0);
  int size() const { return size_; }
  double& operator[](int c) { return values_[size_t(c)]; }
  double operator[](int c) const { return values_[size_t(c)]; }
  double Max() const;

 private:
  int size_;
  std::array<double, kMaxChannels> values_;
};

class WavelengthGroups {
 public:
  // One group: the atmosphere as given.
  explicit WavelengthGroups(const AtmosphereParameters& atmosphere);
  // Groups of one atmosphere: the same radii, density profiles, phase function and sun disc
  // (aerial::Error names the first field that differs), at most kMaxWavelengthGroups of them.
  explicit WavelengthGroups(const std::vector<AtmosphereParameters>& groups);

  int groups() const { return channels_ / 3; }
  int channels() const { return channels_; }
  // The geometry and densities of every group, and the coefficients that choose the paths.
  const Medium& sampling() const { return sampling_; }

  // Per channel, as Medium's per wavelength.
  Channels OpticalDepth(const Column& column) const;
  Channels Transmittance(const Column& column) const;
  double RayleighScattering(int c) const { return rayleigh_scattering_[c]; }
  double MieScattering(int c) const { return mie_scattering_[c]; }
  double SolarIrradiance(int c) const { return solar_irradiance_[c]; }
  double GroundAlbedo(int c) const { return ground_albedo_[c]; }

 private:
  Medium sampling_;
  int channels_;
  Channels rayleigh_scattering_, mie_scattering_, mie_extinction_, absorption_extinction_, solar_irradiance_,
      ground_albedo_;
};

}  // namespace aerial::reference
