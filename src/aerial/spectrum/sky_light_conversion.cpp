#include "aerial/spectrum/sky_light_conversion.h"

#include <cmath>

#include "aerial/spectrum/linear_system.h"
#include "aerial/spectrum/spectral_data.h"
#include "aerial/spectrum/spectral_sampling.h"

namespace aerial::spectrum {
namespace {

constexpr double kIntegralStepNm = 1.0;
// The normal equations' diagonal is raised by this fraction of its mean: it keeps them well
// conditioned where two wavelengths carry nearly the same information, and moves no weight
// measurably.
constexpr double kRidge = 1e-7;

}  // namespace

double SkyLightPath::Factor(double nm) const {
  const double x = nm / 550.0;
  const double ozone = OzoneCrossSection().At(nm) / OzoneCrossSection().At(600.0);
  const double optical_depth =
      rayleigh_depth * std::pow(x, -4.0) + ozone_depth * ozone + aerosol_depth * std::pow(x, -aerosol_exponent);
  return std::pow(x, -4.0 * scattering_power) * std::exp(-optical_depth) *
         (1.0 + reflectance_slope * (nm - 560.0) / 240.0);
}

double SkyLightPath::Radiance(double nm) const { return SolarIrradiance().At(nm) * Factor(nm); }

std::vector<SkyLightPath> SkyLightPaths() {
  std::vector<SkyLightPath> paths;
  for (double a : {0.0, 1.0, 2.0})
    for (double rayleigh : {0.0, 0.1, 0.3, 0.8, 2.0, 4.0})
      for (double ozone : {0.0, 0.1, 0.4, 1.0, 2.0})
        for (auto [aerosol_exponent, aerosol] : {std::pair{0.0, 0.0}, std::pair{1.0, 0.5}, std::pair{2.0, 0.5}})
          for (double slope : {-0.5, 0.0, 0.5})
            paths.push_back({a, rayleigh, ozone, aerosol, aerosol_exponent, slope});
  return paths;
}

Spectrum CieIntegral(const std::function<double(double)>& spectrum) {
  const auto& cmf = Cie1931ColourMatching();
  const int steps = int(std::lround((kVisibleMaxNm - kVisibleMinNm) / kIntegralStepNm));
  Spectrum xyz{};
  for (int i = 0; i <= steps; ++i) {
    const double nm = kVisibleMinNm + i * kIntegralStepNm;
    const double weight = (i == 0 || i == steps ? 0.5 : 1.0) * kIntegralStepNm / YBarIntegralNm();
    const double value = spectrum(nm) * weight;
    for (int c = 0; c < 3; ++c) xyz[c] += cmf[c].At(nm) * value;
  }
  return xyz;
}

std::vector<Spectrum> FitSkyLightConversion(const std::vector<double>& wavelengths_nm) {
  const size_t n = wavelengths_nm.size();
  // Per channel, the normal equations of the weighted least-squares fit.
  std::vector<std::vector<double>> normal(n, std::vector<double>(n, 0.0));
  std::vector<std::vector<double>> right(3, std::vector<double>(n, 0.0));
  for (const SkyLightPath& path : SkyLightPaths()) {
    const Spectrum xyz = CieIntegral([&](double nm) { return path.Radiance(nm); });
    const double weight = 1.0 / (xyz[1] * xyz[1]);
    std::vector<double> samples(n);
    for (size_t j = 0; j < n; ++j) samples[j] = path.Radiance(wavelengths_nm[j]);
    for (size_t j = 0; j < n; ++j) {
      for (size_t k = 0; k < n; ++k) normal[j][k] += weight * samples[j] * samples[k];
      for (int c = 0; c < 3; ++c) right[c][j] += weight * samples[j] * xyz[c];
    }
  }
  double mean_diagonal = 0.0;
  for (size_t j = 0; j < n; ++j) mean_diagonal += normal[j][j] / double(n);
  for (size_t j = 0; j < n; ++j) normal[j][j] += kRidge * mean_diagonal;
  std::vector<Spectrum> weights(n);
  for (int c = 0; c < 3; ++c) {
    const std::vector<double> w = SolveLinearSystem(normal, right[c]);
    for (size_t j = 0; j < n; ++j) weights[j][c] = w[j];
  }
  return weights;
}

}  // namespace aerial::spectrum
