#pragma once
// The wavelengths a spectral computation runs at, and how their values become colour (the CIE 1931
// 2-degree observer). Two samplings:
//  - Midpoint(N), the reference's: N equal bins over 360-830 nm, a wavelength at each bin's
//    centre, integrated by the midpoint rule (Bruneton 2017, model.cc). At 48 wavelengths (every
//    9.8 nm) it is the colour the tables are measured against (docs/colour.md).
//  - ForTables(N), the spectral tables': N equal bins over 395-700 nm, where the observer sees
//    nearly all of sky light, and the XYZ as a linear map of the N values fitted to sky light
//    (sky_light_conversion.h). 12 wavelengths so are within 1e-4 in u'v' of the CIE integral over
//    the fitted family; the midpoint rule at 12 over 360-830 nm is 0.004 off.
// Values at the wavelengths come in groups of three, each of which fills a table's three channels.
#include <array>
#include <functional>
#include <vector>

#include "aerial/spectrum/colour.h"

namespace aerial::spectrum {

inline constexpr double kVisibleMinNm = 360.0, kVisibleMaxNm = 830.0;
// The tables' wavelengths span this range. Within it the fitted weights read the observer's tails
// from the spectrum's slope; moved by 5 nm at either end, 12 wavelengths were 2-5 times farther
// from the integral over the family (the solar spectrum's structure falls differently on them).
inline constexpr double kTableMinNm = 395.0, kTableMaxNm = 700.0;

class SpectralSampling {
 public:
  // count: a positive multiple of 3 (PrecomputeOptions::Validate asks the tables for a multiple of
  // 6 up to 48).
  static SpectralSampling Midpoint(int count);
  static SpectralSampling ForTables(int count);

  const std::vector<double>& wavelengths_nm() const { return wavelengths_nm_; }
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
  SpectralSampling(std::vector<double> wavelengths_nm, std::vector<Spectrum> to_xyz);

  std::vector<double> wavelengths_nm_;
  std::vector<Spectrum> to_xyz_;  // per wavelength, the XYZ of one unit there
};

}  // namespace aerial::spectrum
