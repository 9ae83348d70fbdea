#include "aerial/spectrum/colour.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aerial/spectrum/spectral_sampling.h"

namespace aerial::spectrum {
namespace {

// sRGB's white is D65: x = 0.3127, y = 0.3290 (IEC 61966-2-1), XYZ = (0.9505, 1, 1.0891) maps to
// (1, 1, 1) to the matrix's 4 digits.
TEST(Colour, D65IsWhiteInLinearSrgb) {
  const Spectrum d65 = {0.3127 / 0.3290, 1.0, (1.0 - 0.3127 - 0.3290) / 0.3290};
  Spectrum white = Multiply(LinearSrgbFromXyz(), d65);
  for (double c : white) EXPECT_NEAR(c, 1.0, 1e-3);
  Spectrum back = Multiply(XyzFromLinearSrgb(), white);
  EXPECT_NEAR(back[1], 1.0, 1e-12);
}

// The equal-energy spectrum sits at x = y = 1/3, u'v' = (4/19, 9/19), and a flat spectrum of 1 has
// Y = 1 in aerial's units; 48 wavelengths integrate it to 0.1%.
TEST(Colour, EqualEnergySpectrumIsIlluminantE) {
  const SpectralSampling sampling = SpectralSampling::Midpoint(48);
  Spectrum xyz = sampling.Xyz(std::vector<double>(48, 1.0));
  std::array<double, 2> uv = ChromaticityUv(xyz);
  EXPECT_NEAR(uv[0], 4.0 / 19.0, 1e-3);
  EXPECT_NEAR(uv[1], 9.0 / 19.0, 1e-3);
  EXPECT_NEAR(xyz[1], 1.0, 1e-3);
  // 683 lm/W times the integral of y-bar: 72,983 cd/m^2 per W m^-2 sr^-1 nm^-1.
  EXPECT_NEAR(LuminanceCdM2({0.0, 1.0, 0.0}), 683.0 * 106.857, 1.0);
}

// The groups' matrices add up to the whole conversion (the spectral precompute relies on it).
TEST(Colour, GroupsSumToTheWholeConversion) {
  const SpectralSampling sampling = SpectralSampling::ForTables(12);
  std::vector<double> values = sampling.Sample([](double nm) { return 1.0 + std::sin(nm / 37.0); });
  Spectrum sum{};
  for (int g = 0; g < sampling.groups(); ++g) {
    std::array<double, 3> w = sampling.Group(g);
    Spectrum group_values = {values[3 * g], values[3 * g + 1], values[3 * g + 2]};
    EXPECT_DOUBLE_EQ(w[1], sampling.wavelengths_nm()[3 * g + 1]);
    Spectrum part = Multiply(sampling.GroupToLinearSrgb(g), group_values);
    for (int c = 0; c < 3; ++c) sum[c] += part[c];
  }
  Spectrum whole = sampling.LinearSrgb(values);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], whole[c], 1e-12);
}

}  // namespace
}  // namespace aerial::spectrum
