#include "aerial/image/tone_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "aerial/core/format_number.h"
#include "aerial/error.h"

namespace aerial {
namespace {

// Krzysztof Narkowicz, "ACES Filmic Tone Mapping Curve" (2015): a rational fit
// x (a x + b) / (x (c x + d) + e) to the ACES reference rendering + output transforms. Its
// derivative's numerator, (a d - b c) x^2 + 2 a e x + b e, has only positive coefficients, so
// the curve is strictly increasing on x >= 0 and maps 0 to 0; it tends to a / c > 1, hence the
// clamp to [0, 1].
double AcesFilmic(double x) {
  constexpr double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
  return std::clamp(x * (a * x + b) / (x * (c * x + d) + e), 0.0, 1.0);
}

// sRGB opto-electronic transfer function (IEC 61966-2-1): linear toe below 0.0031308, then a
// 1/2.4 power law, the two meeting continuously.
double SrgbOetf(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

uint8_t Quantize(double unit) {
  return static_cast<uint8_t>(std::lround(std::clamp(unit, 0.0, 1.0) * 255.0));
}

// Negative and NaN radiance (e.g. from a bad sample) show as black rather than poisoning the
// arithmetic. The clamped curve is already 1 from x ~ 7.24 (the root of a x^2 + b x =
// c x^2 + d x + e), so capping at 1e4 changes no output but turns +inf into white instead of
// inf / inf = NaN.
double SanitizeRadiance(double x) {
  if (!(x > 0.0)) return 0.0;
  return std::min(x, 1e4);
}

}  // namespace

double ToneMapChannel(double exposed_radiance) {
  return SrgbOetf(AcesFilmic(SanitizeRadiance(exposed_radiance)));
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
  for (size_t i = 0; i < image.rgba.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c) {
      out[i + c] =
          Quantize(ToneMapChannel(double{image.rgba[i + c]} * options.white_balance[c] * options.exposure));
    }
    const double alpha = image.rgba[i + 3];
    out[i + 3] = Quantize(std::isnan(alpha) ? 0.0 : alpha);
  }
  return out;
}

}  // namespace aerial
