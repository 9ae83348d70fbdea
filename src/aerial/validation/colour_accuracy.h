#pragma once
// The tables' colour against the spectral CPU reference: the chromaticity distance du'v' (CIE 1976
// UCS) and the relative luminance error of the sky radiance, the radiance to a point 10 km along
// the view, the sky irradiance and the sun's irradiance, by band of sun angles and camera
// altitude (docs/colour.md, "Figures").
//
// The reference is ProbeReferenceSpectral (probe/spectral_reference.h) at 48 wavelengths over
// 360-830 nm by the midpoint rule (SpectralSampling::Midpoint): every order, no table, and neither
// the tables' wavelengths nor their conversion. Its Monte Carlo noise is held at a quarter of each
// band's targets where 16 times the base path count allows. It takes hours, so it is kept in a JSON
// file (tests/data/colour_reference.json, `aerial_bench_colour --reference-file`), written view by
// view and continued from the last view it holds.
#include <array>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "aerial/probe.h"
#include "aerial/tables.h"
#include "aerial/view_geometry.h"

namespace aerial::validation {

enum class ColourQuantity { kSkyRadiance, kRadianceToPoint, kSkyIrradiance, kSunIrradiance };
inline constexpr int kColourQuantities = 4;
std::string ToString(ColourQuantity quantity);

// The quantities of one probe, in ColourQuantity's order, and the reference's standard errors (the
// sun's irradiance is a quadrature: 0).
std::array<Spectrum, kColourQuantities> ColourQuantities(const ProbeResult& result);
std::array<Spectrum, kColourQuantities> ColourStdErrors(const ProbeResult& result);

// Sun zenith bands and their targets: daylight 0-60 and the low sun 85-92 degrees, du'v' <= 0.001
// with luminance within 1% and 3%; twilight 93-98 degrees (the blue hour, whose colour the ozone's
// Chappuis band sets), du'v' <= 0.0015 and 3%.
struct ColourBand {
  std::string name;
  std::vector<double> sun_zeniths_deg;
  double chromaticity_target = 0.0;  // du'v'
  double luminance_target = 0.0;     // relative
};
const std::vector<ColourBand>& ColourBands();

// A band's views: cameras on the ground and 10 km up, looking at the zenith, 60 and 85 degrees
// from it, toward the sun and away from it; the first view of the first band is noon's zenith.
std::vector<ViewAngles> ColourViews(const ColourBand& band);

// The reference's wavelengths (SpectralSampling::Midpoint) and the distance of the radiance to a
// point.
inline constexpr int kColourReferenceWavelengths = 48;
inline constexpr double kColourPointDistanceM = 10e3;
// A reference value takes 4, 16 then 64 times the base paths while its noise is above its goal.
// Where 64 times is not enough (twilight, whose light is all orders >= 2), the noise is what a
// comparison is held to, not the target.
inline constexpr int kMaxColourPathsFactor = 64;

struct ColourSample {
  std::string band;
  ViewAngles view;
  std::array<Spectrum, kColourQuantities> value{}, std_error{};  // linear sRGB
  int paths = 0;
};

struct ColourReference {
  int wavelengths = kColourReferenceWavelengths;
  int orders = 0;  // reference::kAllOrders for the whole series
  int paths_per_query = 0;
  // Per quantity, the luminance (Y) below which a value is not compared: 1e-4 of its noon value
  // (the noon zenith sky's for both radiances), as over the physical-sky grid (sky_accuracy.h).
  std::array<double, kColourQuantities> floors{};
  std::vector<ColourSample> samples;
};

// The standard errors of a colour's u'v' and of its relative luminance, from its channels'
// independent standard errors (linear sRGB).
double ChromaticityNoise(const Spectrum& linear_srgb, const Spectrum& std_error);
double LuminanceNoise(const Spectrum& linear_srgb, const Spectrum& std_error);

// The views of every band, in the order a reference holds its samples.
size_t ColourReferenceViewCount();
bool IsComplete(const ColourReference& reference);

using ColourProgress = std::function<void(size_t done, size_t total, int paths)>;
// Computes the samples that `reference` lacks (all of them for a new one, whose orders and
// paths_per_query are set), after those it holds (a reference cut short), and
// calls after_each_sample with it after each one, so that hours of work can be kept as they go.
// Throws aerial::Error where the samples held are not the first views of ColourBands().
void ContinueColourReference(const AtmosphereParameters& atmosphere, ColourReference& reference,
                             const ColourProgress& progress = {},
                             const std::function<void(const ColourReference&)>& after_each_sample = {});
// One sample recomputed with its own path count: the same numbers as when it was made, as long as
// the reference code has not changed.
ColourSample RecomputeColourSample(const AtmosphereParameters& atmosphere, const ColourReference& reference,
                                   const ColourSample& sample);

void WriteColourReference(const ColourReference& reference, const std::filesystem::path& path);
// Throws aerial::Error naming the file and what is wrong with it.
ColourReference ReadColourReference(const std::filesystem::path& path);

struct ColourError {
  double chromaticity = 0.0;  // du'v'
  double luminance = 0.0;     // |Y / Y_reference - 1|
};
// Both colours in linear sRGB.
ColourError CompareColour(const Spectrum& measured, const Spectrum& expected);

// The compared values of one quantity in one band at one camera altitude.
struct ColourRegion {
  ColourQuantity quantity;
  std::string band;
  double altitude_m = 0.0;
  std::vector<ColourError> errors;
  std::vector<double> chromaticity_noise;  // the reference's, per compared value
  std::vector<ViewAngles> views;           // of each compared value
  double MedianChromaticity() const;
  double MaxChromaticity() const;
  double MedianLuminance() const;
  double MaxLuminance() const;
  double MaxChromaticityNoise() const;
  // The view of the largest du'v' (the region must hold a value).
  const ViewAngles& WorstChromaticityView() const;
};

std::vector<ColourRegion> CompareColourWithTables(const Tables& tables, const ColourReference& reference);

// A Markdown table: one row per quantity, band and altitude that holds values, du'v' and luminance
// (median / max), the view of the largest du'v' and the reference's largest chromaticity noise.
std::string FormatColourAccuracy(const std::string& tables_name, const std::vector<ColourRegion>& regions);

}  // namespace aerial::validation
