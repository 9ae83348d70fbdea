#pragma once
// Colour from spectra: CIE 1931 XYZ, linear sRGB (ITU-R BT.709 primaries, D65 white; IEC
// 61966-2-1), chromaticity u'v' (CIE 1976 UCS) and luminance.
//
// aerial keeps spectral units in its colour values: X, Y, Z and linear sRGB are divided by the
// integral of y-bar, so that Y is the y-bar-weighted mean spectral radiance (W m^-2 sr^-1 nm^-1)
// and a flat spectrum of 1 has Y = 1. Luminance in cd/m^2 is then 683 * YBarIntegralNm() * Y.
#include <array>

#include "aerial/atmosphere.h"

namespace aerial::spectrum {

using Matrix3 = std::array<std::array<double, 3>, 3>;  // row-major

Spectrum Multiply(const Matrix3& m, const Spectrum& v);
Matrix3 Multiply(const Matrix3& a, const Matrix3& b);
Matrix3 Inverse(const Matrix3& m);  // m must be invertible

// IEC 61966-2-1 (sRGB), the matrix Bruneton 2017 uses too.
const Matrix3& LinearSrgbFromXyz();
const Matrix3& XyzFromLinearSrgb();

// CIE 1976 u' and v' of an XYZ colour ({0, 0} for black).
std::array<double, 2> ChromaticityUv(const Spectrum& xyz);
// The distance between two colours' u'v' chromaticities.
double ChromaticityDistance(const Spectrum& xyz_a, const Spectrum& xyz_b);
// cd/m^2 of a colour in aerial's units (Y as above).
double LuminanceCdM2(const Spectrum& xyz);

}  // namespace aerial::spectrum
