#include "aerial/spectrum/spectral_sampling.h"

#include "aerial/spectrum/spectral_data.h"

namespace aerial::spectrum {

SpectralSampling::SpectralSampling(int count)
    : bin_width_nm_((kVisibleMaxNm - kVisibleMinNm) / count) {
  for (int i = 0; i < count; ++i) wavelengths_nm_.push_back(kVisibleMinNm + (i + 0.5) * bin_width_nm_);
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
  const auto& cmf = Cie1931ColourMatching();
  Spectrum xyz{};
  // Midpoint rule, divided by the integral of y-bar (colour.h's units).
  const double weight = bin_width_nm_ / YBarIntegralNm();
  for (size_t i = 0; i < wavelengths_nm_.size(); ++i)
    for (int c = 0; c < 3; ++c) xyz[c] += cmf[c].At(wavelengths_nm_[i]) * values[i] * weight;
  return xyz;
}

Spectrum SpectralSampling::LinearSrgb(const std::vector<double>& values) const {
  return Multiply(LinearSrgbFromXyz(), Xyz(values));
}

Spectrum SpectralSampling::WavelengthToLinearSrgb(int index) const {
  std::vector<double> unit(wavelengths_nm_.size(), 0.0);
  unit[index] = 1.0;
  return LinearSrgb(unit);
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
