#include "aerial/scene/noise.h"

#include <array>
#include <cmath>
#include <numbers>

namespace aerial {

uint32_t Hash(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

uint32_t Hash(uint32_t a, uint32_t b, uint32_t c) {
  // Chain the inputs through the finalizer so (a, b, c) and (b, a, c) differ.
  return Hash(a ^ Hash(b ^ Hash(c + 0x9e3779b9U)));
}

double UnitFromHash(uint32_t h) { return static_cast<double>(h >> 8) / 16777216.0; }

namespace {

double Fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// The unit vector at the angle 2 pi k / 2^24 for 24 bits k, as the sum of two angles from tables
// of 4096 each (cos(a + b) = cos a cos b - sin a sin b).
class UnitCircle {
 public:
  UnitCircle() {
    for (int i = 0; i < kSize; ++i) {
      double coarse = 2.0 * std::numbers::pi * i / kSize, fine = coarse / kSize;
      coarse_[size_t(i)] = {std::cos(coarse), std::sin(coarse)};
      fine_[size_t(i)] = {std::cos(fine), std::sin(fine)};
    }
  }
  std::array<double, 2> At(uint32_t k) const {
    const std::array<double, 2>&a = coarse_[k >> 12], &b = fine_[k & (kSize - 1)];
    return {a[0] * b[0] - a[1] * b[1], a[1] * b[0] + a[0] * b[1]};
  }

 private:
  static constexpr int kSize = 4096;  // 2^12: two tables cover the 24 bits
  std::array<std::array<double, 2>, kSize> coarse_, fine_;
};

// Dot product of the lattice point's unit gradient with the offset to it.
double Corner(int64_t ix, int64_t iy, uint32_t seed, double dx, double dy) {
  std::array<double, 2> gradient = UnitGradient(Hash(static_cast<uint32_t>(ix), static_cast<uint32_t>(iy), seed));
  return gradient[0] * dx + gradient[1] * dy;
}

}  // namespace

std::array<double, 2> UnitGradient(uint32_t h) {
  static const UnitCircle circle;
  return circle.At(h >> 8);  // UnitFromHash(h) = (h >> 8) / 2^24
}

double GradientNoise(double x, double y, uint32_t seed) {
  double fx = std::floor(x), fy = std::floor(y);
  // The hash reads lattice coordinates modulo 2^32, so they are reduced there first (exactly:
  // fmod is exact), which also keeps a far-away x within int64 (converting it would overflow).
  auto lattice = [](double f) { return static_cast<int64_t>(std::fmod(f, 4294967296.0)); };
  int64_t ix = lattice(fx), iy = lattice(fy);
  double dx = x - fx, dy = y - fy;
  double u = Fade(dx), v = Fade(dy);
  double bottom = Corner(ix, iy, seed, dx, dy) * (1 - u) + Corner(ix + 1, iy, seed, dx - 1, dy) * u;
  double top = Corner(ix, iy + 1, seed, dx, dy - 1) * (1 - u) +
               Corner(ix + 1, iy + 1, seed, dx - 1, dy - 1) * u;
  return bottom * (1 - v) + top * v;
}

}  // namespace aerial
