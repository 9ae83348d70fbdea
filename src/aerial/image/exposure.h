#pragma once
// A camera's exposure for display images (PNG, the viewer), physically based: the exposure value
// at ISO 100, EV100, fixed or metered from the frame's log-average luminance (Lagarde & de
// Rousiers 2014, "Moving Frostbite to PBR", sec. 5.1). EXR output keeps the radiance and never
// sees it.
#include <array>

#include "aerial/image.h"

namespace aerial {

// Luminance (cd/m^2) of a pixel whose channels hold spectral radiance (W/m^2/sr/nm) at the
// atmosphere's three wavelengths (680, 550, 440 nm): 683 lm/W times the photopic curve's integral
// (106.857 nm, CIE 1931 V) times the Rec. 709 luminance weights' average of the three, i.e. the
// three samples stand for a spectrum flat over each channel's band.
inline constexpr double kRadiancePerNmToLuminance = 683.0 * 106.857;
inline constexpr std::array<double, 3> kLuminancePerChannel = {
    kRadiancePerNmToLuminance * 0.2126, kRadiancePerNmToLuminance * 0.7152, kRadiancePerNmToLuminance * 0.0722};
double LuminanceOfRadiance(const float* rgb);

// The luminance a camera's meter reads, in cd/m^2: exp(mean(ln L)) over the middle of the image's
// pixels sorted by luminance, from kMeteredLowFraction to kMeteredHighFraction of them (the
// histogram-clipped average of Unreal's and Frostbite's automatic exposure). Over all pixels, a
// dark space above a view from 30 km or a bright sky over a dim ground moved the average so far
// that the median pixel came out at 71% (high-altitude) or 23% (sunset) of full scale; over the
// middle 40%, every preset's median pixel is 32-57% but twilight's 24% (its ground, lit by the
// sky alone, is 5 stops under the horizon's glow; measured on 160x90 renders of each preset).
// Non-finite and non-positive pixels count as kMinLuminance, so that a black corner cannot drag
// the average to zero.
inline constexpr double kMinLuminance = 1e-4;
inline constexpr double kMeteredLowFraction = 0.3, kMeteredHighFraction = 0.7;
double LogAverageLuminance(const ImageRgbF& image);

// EV100 that exposes an average scene luminance L to the meter's calibration:
// EV100 = log2(L S / K), S = 100, K = 12.5 (Lagarde & de Rousiers 2014, eq. 59).
double Ev100FromAverageLuminance(double luminance);

// The multiplier that takes spectral radiance to the tone map's input for a camera at EV100:
// the luminance of the brightest unclipped point is 1.2 * 2^EV100 (saturation-based speed,
// eq. 64); that luminance maps to 1.
double RadianceMultiplierFromEv100(double ev100);
// Its inverse: the EV100 of a camera whose radiance multiplier is `multiplier`.
double Ev100FromRadianceMultiplier(double multiplier);

// The gains that make the sun's colour white, keeping their mean at 1 (the white balance of
// Bruneton 2017's demo): mean(sun) / sun per channel, for pictures; physical output never has it.
// Defined for every sun: a channel the sun lights less than a millionth of its mean (a dark
// channel of an rgb sun, valid in an atmosphere file) gets the gain kMaxWhiteBalanceGain, which
// leaves it as dark as the sun leaves it, instead of an infinite one; with no sunlight at all the
// gains are 1.
inline constexpr double kMaxWhiteBalanceGain = 1e6;
std::array<double, 3> WhiteBalanceForSun(const std::array<double, 3>& sun_colour);

// How an image is exposed: metered (automatic), a fixed EV100, or a plain radiance multiplier.
struct Exposure {
  enum class Mode { kAuto, kEv100, kMultiplier };
  Mode mode = Mode::kAuto;
  double value = 0.0;  // the EV100 (kEv100) or the multiplier (kMultiplier)

  // The radiance multiplier for this image (ToneMapOptions::exposure).
  double MultiplierFor(const ImageRgbF& image) const;
  // The same for a metered average luminance (cd/m^2), as the viewer meters on the GPU.
  double MultiplierForAverage(double average_luminance) const;
  // The EV100 of a fixed exposure (kEv100 or kMultiplier).
  double FixedEv100() const;
};

}  // namespace aerial
