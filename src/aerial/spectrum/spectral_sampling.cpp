#include "aerial/spectrum/spectral_sampling.h"

#include <map>
#include <mutex>

#include "aerial/error.h"
#include "aerial/spectrum/sky_light_conversion.h"
#include "aerial/spectrum/spectral_data.h"

namespace aerial::spectrum {
namespace {

std::vector<double> BinCentres(int count, double min_nm, double max_nm) {
  if (count < 3 || count % 3 != 0) throw Error("wavelengths", std::to_string(count), "a positive multiple of 3");
  const double width = (max_nm - min_nm) / count;
  std::vector<double> nm;
  for (int i = 0; i < count; ++i) nm.push_back(min_nm + (i + 0.5) * width);
  return nm;
}

}  // namespace

SpectralSampling::SpectralSampling(std::vector<double> wavelengths_nm, std::vector<Spectrum> to_xyz)
    : wavelengths_nm_(std::move(wavelengths_nm)), to_xyz_(std::move(to_xyz)) {}

SpectralSampling SpectralSampling::Midpoint(int count) {
  std::vector<double> nm = BinCentres(count, kVisibleMinNm, kVisibleMaxNm);
  const auto& cmf = Cie1931ColourMatching();
  // Each bin's width, divided by the integral of y-bar (colour.h's units).
  const double weight = (kVisibleMaxNm - kVisibleMinNm) / count / YBarIntegralNm();
  std::vector<Spectrum> to_xyz;
  for (double w : nm) to_xyz.push_back({cmf[0].At(w) * weight, cmf[1].At(w) * weight, cmf[2].At(w) * weight});
  return SpectralSampling(std::move(nm), std::move(to_xyz));
}

SpectralSampling SpectralSampling::ForTables(int count) {
  std::vector<double> nm = BinCentres(count, kTableMinNm, kTableMaxNm);
  // The fit takes tens of milliseconds; every user of the tables' sampling asks for the same few.
  static std::mutex mutex;
  static std::map<int, std::vector<Spectrum>> fitted;
  std::lock_guard lock(mutex);
  auto it = fitted.find(count);
  if (it == fitted.end()) it = fitted.emplace(count, FitSkyLightConversion(nm)).first;
  return SpectralSampling(std::move(nm), it->second);
}

std::array<double, 3> SpectralSampling::Group(int group) const {
  return {wavelengths_nm_[3 * group], wavelengths_nm_[3 * group + 1], wavelengths_nm_[3 * group + 2]};
}

std::vector<double> SpectralSampling::Sample(const std::function<double(double)>& f) const {
  std::vector<double> values;
  for (double w : wavelengths_nm_) values.push_back(f(w));
  return values;
}

Spectrum SpectralSampling::Xyz(const std::vector<double>& values) const {
  Spectrum xyz{};
  for (size_t i = 0; i < wavelengths_nm_.size(); ++i)
    for (int c = 0; c < 3; ++c) xyz[c] += to_xyz_[i][c] * values[i];
  return xyz;
}

Spectrum SpectralSampling::LinearSrgb(const std::vector<double>& values) const {
  return Multiply(LinearSrgbFromXyz(), Xyz(values));
}

Spectrum SpectralSampling::WavelengthToLinearSrgb(int index) const {
  return Multiply(LinearSrgbFromXyz(), to_xyz_[index]);
}

Matrix3 SpectralSampling::GroupToLinearSrgb(int group) const {
  Matrix3 from_group{};
  for (int k = 0; k < 3; ++k) {
    Spectrum column = WavelengthToLinearSrgb(3 * group + k);
    for (int c = 0; c < 3; ++c) from_group[c][k] = column[c];
  }
  return from_group;
}

}  // namespace aerial::spectrum
