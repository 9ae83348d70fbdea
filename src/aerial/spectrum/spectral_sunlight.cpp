#include "aerial/spectrum/spectral_sunlight.h"

#include <algorithm>
#include <cmath>

#include "aerial/spectrum/higher_orders.h"

namespace aerial::spectrum {
namespace {

// A constituent's extinction: per channel in the render-time atmosphere, and at any wavelength.
struct Constituent {
  Spectrum channels;
  double (SpectralAtmosphere::*at)(double) const;
};

// How far the columns of `basis` are from dependent: det(B^T B) over the product of its diagonal
// (Hadamard's ratio), 1 for orthogonal columns and 0 for dependent ones. At most three columns.
double HadamardRatio(const std::vector<std::vector<double>>& basis) {
  const size_t k = basis[0].size();
  double gram[3][3] = {};
  for (size_t a = 0; a < k; ++a)
    for (size_t b = 0; b < k; ++b)
      for (const std::vector<double>& row : basis) gram[a][b] += row[a] * row[b];
  double det = k == 1   ? gram[0][0]
               : k == 2 ? gram[0][0] * gram[1][1] - gram[0][1] * gram[1][0]
                        : gram[0][0] * (gram[1][1] * gram[2][2] - gram[1][2] * gram[2][1]) -
                              gram[0][1] * (gram[1][0] * gram[2][2] - gram[1][2] * gram[2][0]) +
                              gram[0][2] * (gram[1][0] * gram[2][1] - gram[1][1] * gram[2][0]);
  double diagonal = 1.0;
  for (size_t a = 0; a < k; ++a) diagonal *= gram[a][a];
  return det / diagonal;
}

// Each wavelength's share of each channel of LinearSrgb(E * beta).
std::vector<Spectrum> Shares(const SpectralSampling& sampling, const std::vector<double>& weighted) {
  Spectrum total = sampling.LinearSrgb(weighted);
  std::vector<Spectrum> shares(weighted.size());
  for (size_t j = 0; j < weighted.size(); ++j) {
    Spectrum colour = sampling.WavelengthToLinearSrgb(int(j));
    for (int c = 0; c < 3; ++c) shares[j][c] = total[c] > 0.0 ? colour[c] * weighted[j] / total[c] : 0.0;
  }
  return shares;
}

}  // namespace

SpectralSunlight MakeSpectralSunlight(const SpectralAtmosphere& atmosphere, const AtmosphereParameters& linear_srgb,
                                      const SpectralSampling& sampling) {
  // The constituents present: an absent one (no ozone) has no column density to recover.
  std::vector<Constituent> constituents;
  for (const Constituent& k : {Constituent{linear_srgb.rayleigh_scattering, &SpectralAtmosphere::RayleighScattering},
                               Constituent{linear_srgb.mie_extinction, &SpectralAtmosphere::MieExtinction},
                               Constituent{linear_srgb.absorption_extinction, &SpectralAtmosphere::AbsorptionExtinction}})
    if (std::max({k.channels[0], k.channels[1], k.channels[2]}) > 0.0) constituents.push_back(k);

  // tau_rgb = A N, A_ck = constituent k's coefficient in channel c, scaled to 1 at its largest so
  // that the normal equations of LeastSquaresWeights are well conditioned. tau(lambda) =
  // sigma(lambda) . N is the least-squares fit of tau_rgb by A's columns read at sigma(lambda): with
  // three constituents it interpolates, g = A^-T sigma.
  std::vector<std::vector<double>> basis(3, std::vector<double>(constituents.size()));
  std::vector<double> scale(constituents.size());
  for (size_t k = 0; k < constituents.size(); ++k) {
    const Spectrum& a = constituents[k].channels;
    scale[k] = std::max({a[0], a[1], a[2]});
    for (int c = 0; c < 3; ++c) basis[c][k] = a[c] / scale[k];
  }
  // Where two constituents' channel coefficients are (nearly) proportional, their column densities
  // are not determined and g would amplify rounding without bound. Earth's ratio is 6e-4 (g up to
  // 16 in magnitude, at 380 and 810 nm); proportional columns give rounding's 1e-16.
  if (constituents.empty() || HadamardRatio(basis) < 1e-8) return {};
  SpectralSunlight sunlight;
  const std::vector<double>& nm = sampling.wavelengths_nm();
  for (double lambda : nm) {
    std::vector<double> sigma(constituents.size());
    for (size_t k = 0; k < constituents.size(); ++k) sigma[k] = (atmosphere.*constituents[k].at)(lambda) / scale[k];
    std::vector<double> g = LeastSquaresWeights(basis, sigma);
    sunlight.exponents.push_back({g[0], g[1], g[2]});
  }

  std::vector<double> sun = sampling.Sample([&](double lambda) { return atmosphere.SolarIrradiance(lambda); });
  auto weighted = [&](double (SpectralAtmosphere::*beta)(double) const) {
    std::vector<double> values = sun;
    for (size_t j = 0; j < values.size(); ++j) values[j] *= (atmosphere.*beta)(nm[j]);
    return values;
  };
  sunlight.rayleigh_shares = Shares(sampling, weighted(&SpectralAtmosphere::RayleighScattering));
  sunlight.mie_shares = Shares(sampling, weighted(&SpectralAtmosphere::MieScattering));
  sunlight.direct_shares = Shares(sampling, sun);
  return sunlight;
}

Spectrum PathSunlight(const SpectralSunlight& sunlight, const std::vector<Spectrum>& shares,
                      const Spectrum& channel_optical_depth) {
  Spectrum light{};
  for (size_t j = 0; j < sunlight.exponents.size(); ++j) {
    const Spectrum& g = sunlight.exponents[j];
    double optical_depth = g[0] * channel_optical_depth[0] + g[1] * channel_optical_depth[1] +
                           g[2] * channel_optical_depth[2];
    double transmittance = std::exp(-std::max(optical_depth, 0.0));
    for (int c = 0; c < 3; ++c) light[c] += shares[j][c] * transmittance;
  }
  return light;
}

}  // namespace aerial::spectrum
