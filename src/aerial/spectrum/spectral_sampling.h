#pragma once
// The wavelengths a spectral precompute runs at, and how their values become colour: N equal bins
// over 360-830 nm with a wavelength at each bin's centre, integrated against the CIE 1931
// colour-matching functions by the midpoint rule (Bruneton 2017, model.cc: 15 wavelengths, in
// groups of three that each fill a table's three channels).
#include <array>
#include <functional>
#include <vector>

#include "aerial/spectrum/colour.h"

namespace aerial::spectrum {

inline constexpr double kVisibleMinNm = 360.0, kVisibleMaxNm = 830.0;

class SpectralSampling {
 public:
  // count: a multiple of 3 in [3, 48] (PrecomputeOptions::Validate asks the tables for a multiple
  // of 6).
  explicit SpectralSampling(int count);

  const std::vector<double>& wavelengths_nm() const { return wavelengths_nm_; }
  double bin_width_nm() const { return bin_width_nm_; }
  int groups() const { return int(wavelengths_nm_.size()) / 3; }
  std::array<double, 3> Group(int group) const;

  // The values of f at the wavelengths.
  std::vector<double> Sample(const std::function<double(double)>& f) const;
  // XYZ and linear sRGB (colour.h's units) of a spectrum given at the wavelengths.
  Spectrum Xyz(const std::vector<double>& values) const;
  Spectrum LinearSrgb(const std::vector<double>& values) const;
  // What one unit at wavelength `index` (and zero elsewhere) adds to LinearSrgb.
  Spectrum WavelengthToLinearSrgb(int index) const;
  // The matrix that takes a group's three values to its part of LinearSrgb (summed over groups).
  Matrix3 GroupToLinearSrgb(int group) const;

 private:
  std::vector<double> wavelengths_nm_;
  double bin_width_nm_;
};

}  // namespace aerial::spectrum
