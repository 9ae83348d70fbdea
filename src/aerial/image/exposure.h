#pragma once
// A camera's exposure for display images (PNG, the viewer), physically based: the exposure value
// at ISO 100, EV100, fixed or metered from the frame (Lagarde & de Rousiers 2014, "Moving
// Frostbite to PBR", sec. 5.1), with a highlight-weighted meter's limit. EXR output keeps the
// radiance and never sees it.
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
// histogram-clipped average of Unreal's and Frostbite's automatic exposure): over all pixels, a
// dark space above a view from 30 km or a bright sky over a dim ground would move it by stops.
// Non-finite and non-positive pixels count as kMinLuminance, so that a black corner cannot drag
// the average to zero.
inline constexpr double kMinLuminance = 1e-4;
inline constexpr double kMeteredLowFraction = 0.3, kMeteredHighFraction = 0.7;
double LogAverageLuminance(const ImageRgbF& image);

// What the automatic exposure reads from a frame: the log-average luminance above (cd/m^2), and
// the highlight: the kHighlightFraction quantile of each pixel's brightest channel after the white
// balance, in the same units (times kRadiancePerNmToLuminance), so that the sun's disc and a few
// glints are left out but a sunset's glow is not.
inline constexpr double kHighlightFraction = 0.99;
struct MeterReading {
  double average_luminance = kMinLuminance;
  double highlight = kMinLuminance;
};
MeterReading ReadMeter(const ImageRgbF& image, const std::array<double, 3>& white_balance);

// The EV100 a reading asks for. The average is taken to mid grey, 0.18 of the display curve's
// input (its identity part); then, as a camera's highlight-weighted mode does, the exposure is
// lowered until the highlight is at kHighlightWhite, the start of the curve's shoulder's last
// stop, so that a bright sky over a dark foreground keeps its colour instead of bleaching to
// white; by at most kMaxHighlightStops, so that the foreground is not lost to black.
inline constexpr double kMeteredGrey = 0.18;
inline constexpr double kHighlightWhite = 1.0;
inline constexpr double kMaxHighlightStops = 3.0;
double Ev100FromMeter(const MeterReading& reading);

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

  // The radiance multiplier for this image (ToneMapOptions::exposure), shown with these white
  // balance gains.
  double MultiplierFor(const ImageRgbF& image, const std::array<double, 3>& white_balance = {1.0, 1.0, 1.0}) const;
  // The same for a meter's reading, as the viewer meters on the GPU.
  double MultiplierForReading(const MeterReading& reading) const;
  // The EV100 of a fixed exposure (kEv100 or kMultiplier).
  double FixedEv100() const;
};

}  // namespace aerial
