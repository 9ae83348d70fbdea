#include "aerial/image/tone_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "aerial/core/format_number.h"
#include "aerial/error.h"
#include "aerial/scene/noise.h"

namespace aerial {
namespace {

// Khronos PBR Neutral's constants: compression starts at 0.8 less the toe's 0.04; the desaturation
// rate of the compressed part.
constexpr double kStartCompression = 0.8 - 0.04;
constexpr double kDesaturation = 0.15;

// sRGB opto-electronic transfer function (IEC 61966-2-1): linear toe below 0.0031308, then a
// 1/2.4 power law, the two meeting continuously.
double SrgbOetf(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

uint8_t Quantize(double unit) {
  return static_cast<uint8_t>(std::lround(std::clamp(unit, 0.0, 1.0) * 255.0));
}

// Negative and NaN radiance (e.g. from a bad sample) show as black rather than poisoning the
// arithmetic; capping at 1e4 changes no output (the curve is within 1e-5 of white there) but turns
// +inf into white instead of inf / inf = NaN.
double SanitizeRadiance(double x) {
  if (!(x > 0.0)) return 0.0;
  return std::min(x, 1e4);
}

}  // namespace

std::array<double, 3> DisplayCurve(const std::array<double, 3>& exposed_radiance) {
  std::array<double, 3> c;
  for (int i = 0; i < 3; ++i) c[i] = SanitizeRadiance(exposed_radiance[i]);
  // The toe: a shift down of the darkest channel, quadratic below 0.08, 0.04 above.
  double x = std::min({c[0], c[1], c[2]});
  double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  for (double& v : c) v -= offset;
  double peak = std::max({c[0], c[1], c[2]});
  if (peak < kStartCompression) return c;
  constexpr double d = 1.0 - kStartCompression;
  double new_peak = 1.0 - d * d / (peak + d - kStartCompression);
  double g = 1.0 - 1.0 / (kDesaturation * (peak - new_peak) + 1.0);
  for (double& v : c) v = v * new_peak / peak * (1.0 - g) + new_peak * g;
  return c;
}

std::array<double, 3> ToneMapColour(const std::array<double, 3>& exposed_radiance) {
  std::array<double, 3> c = DisplayCurve(exposed_radiance);
  for (double& v : c) v = SrgbOetf(std::clamp(v, 0.0, 1.0));
  return c;
}

// Encoded values from here up round to 255 without the dither (display.glsl's kDitheredBelowLinear).
constexpr double kDitheredBelow = 1.0 - 0.5 / 255.0;

double DitherSteps(uint32_t x, uint32_t y) {
  // Two uniform numbers in [0, 1) from one hash each; their difference is triangular on (-1, 1),
  // whose noise does not depend on the signal (Lipshitz, Wannamaker & Vanderkooy 1992).
  // The one-input Hash is exact in GLSL's uint arithmetic, which tone_map.glsl repeats.
  uint32_t a = Hash(x + Hash(y));
  uint32_t b = Hash(a);
  return UnitFromHash(a) - UnitFromHash(b);
}

std::vector<uint8_t> ToneMapToSrgb8(const ImageRgbF& image, const ToneMapOptions& options) {
  CheckImageSize(image);
  // A zero, negative or non-finite exposure would silently give a black or NaN image.
  if (!(options.exposure > 0.0) || !std::isfinite(options.exposure))
    throw Error("exposure", FormatNumber(options.exposure), "a finite number > 0");
  for (double gain : options.white_balance)
    if (!(gain > 0.0) || !std::isfinite(gain))
      throw Error("white balance", FormatNumber(gain), "finite gains > 0");
  std::vector<uint8_t> out(image.rgba.size());
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const float* in = image.pixel(x, y);
      size_t i = (size_t(y) * size_t(image.width) + size_t(x)) * 4;
      std::array<double, 3> exposed;
      for (int c = 0; c < 3; ++c) exposed[c] = double{in[c]} * options.white_balance[c] * options.exposure;
      std::array<double, 3> display = ToneMapColour(exposed);
      double dither = options.dither ? DitherSteps(uint32_t(x), uint32_t(y)) / 255.0 : 0.0;
      // Black and white stay undithered: no specks in a clipped sun or a black corner. White is
      // whatever rounds to 255 undithered, since the curve only nears 1.
      for (int c = 0; c < 3; ++c)
        out[i + c] = Quantize(display[c] > 0.0 && display[c] < kDitheredBelow ? display[c] + dither : display[c]);
      const double alpha = in[3];
      out[i + 3] = Quantize(std::isnan(alpha) ? 0.0 : alpha);
    }
  }
  return out;
}

}  // namespace aerial
