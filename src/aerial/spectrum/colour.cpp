#include "aerial/spectrum/colour.h"

#include <cmath>

#include "aerial/spectrum/spectral_data.h"

namespace aerial::spectrum {

Spectrum Multiply(const Matrix3& m, const Spectrum& v) {
  Spectrum out{};
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
  return out;
}

Matrix3 Multiply(const Matrix3& a, const Matrix3& b) {
  Matrix3 out{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
  return out;
}

const Matrix3& LinearSrgbFromXyz() {
  static const Matrix3 m = {{{3.2406, -1.5372, -0.4986},
                             {-0.9689, 1.8758, 0.0415},
                             {0.0557, -0.2040, 1.0570}}};
  return m;
}

Matrix3 Inverse(const Matrix3& m) {
  double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  Matrix3 inv{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      // Cofactor of m[j][i] over the determinant.
      int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      inv[i][j] = (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) / det;
    }
  return inv;
}

const Matrix3& XyzFromLinearSrgb() {
  static const Matrix3 inverse = Inverse(LinearSrgbFromXyz());
  return inverse;
}

std::array<double, 2> ChromaticityUv(const Spectrum& xyz) {
  double denominator = xyz[0] + 15.0 * xyz[1] + 3.0 * xyz[2];
  if (denominator <= 0.0) return {0.0, 0.0};
  return {4.0 * xyz[0] / denominator, 9.0 * xyz[1] / denominator};
}

double ChromaticityDistance(const Spectrum& xyz_a, const Spectrum& xyz_b) {
  std::array<double, 2> a = ChromaticityUv(xyz_a), b = ChromaticityUv(xyz_b);
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

double LuminanceCdM2(const Spectrum& xyz) { return kMaxLuminousEfficacy * YBarIntegralNm() * xyz[1]; }

}  // namespace aerial::spectrum
