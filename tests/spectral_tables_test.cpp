// The spectral tables (--colour spectral) against the spectral CPU reference, in colour, and the
// three-wavelength tables against the same reference: what the spectral mode buys.
#include <gtest/gtest.h>

#include <cmath>

#include "aerial/probe/spectral_reference.h"
#include "aerial/probe/table_probe.h"
#include "aerial/spectrum/colour.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

// Single scattering only: the reference is then a deterministic quadrature, so the comparison is
// free of Monte Carlo noise and quick (the orders above it: aerial_bench_colour, docs/colour.md).
// Default resolutions: the small tables' own luminance error reaches 1% 10 km up.
PrecomputeOptions SingleScattering(ColourMode colour) {
  PrecomputeOptions options = PrecomputeOptions::Default();
  options.orders = 1;
  options.close_series = false;
  options.colour = colour;
  return options;
}

struct ColourError {
  double chromaticity, luminance;
};

ColourError Compare(const Spectrum& linear_srgb, const Spectrum& expected_linear_srgb) {
  const auto& to_xyz = spectrum::XyzFromLinearSrgb();
  Spectrum measured = spectrum::Multiply(to_xyz, linear_srgb), expected = spectrum::Multiply(to_xyz, expected_linear_srgb);
  return {spectrum::ChromaticityDistance(measured, expected), std::abs(measured[1] / expected[1] - 1.0)};
}

// Daylight views: the zenith and a view 60 degrees down across the sun's plane, under a sun at 30
// degrees, from the ground and 10 km up.
const std::vector<ViewAngles> kViews = {{0.0, 0.0, 30.0, 0.0}, {0.0, 60.0, 30.0, 90.0},
                                        {10e3, 60.0, 30.0, 90.0}, {0.0, 80.0, 60.0, 180.0}};

// The tables' values at kViews, and the spectral reference's (single scattering, the default
// wavelength count).
struct ViewsCompared {
  std::vector<ProbeResult> tables, reference;
};

ViewsCompared CompareViews(ColourMode colour) {
  const AtmosphereTables& tables = CachedTables(SingleScattering(colour));
  std::vector<ProbeQuery> queries;
  for (const ViewAngles& view : kViews) queries.push_back({ToRayParameters(view, AtmosphereParameters::Earth())});
  ViewsCompared compared{ProbeTables(tables, queries), {}};
  for (const ProbeQuery& query : queries)
    compared.reference.push_back(ProbeReferenceSpectral(AtmosphereParameters::Earth(), query.ray, std::nullopt, 1,
                                                        PrecomputeOptions{}.spectral_wavelengths));
  return compared;
}

class SpectralTables : public GpuTest {};

// The daylight target, du'v' <= 0.003 and luminance within 1%, for the sky radiance and
// the sun's irradiance; measured 3e-5 and 0.1% at the second view.
TEST_F(SpectralTables, MatchTheSpectralReferenceInColour) {
  ViewsCompared c = CompareViews(ColourMode::kSpectral);
  for (size_t i = 0; i < kViews.size(); ++i) {
    for (auto [measured, wanted] : {std::pair{c.tables[i].sky_radiance, c.reference[i].sky_radiance},
                                    std::pair{c.tables[i].sun_irradiance, c.reference[i].sun_irradiance}}) {
      ColourError error = Compare(measured, wanted);
      EXPECT_LT(error.chromaticity, 0.003) << "view " << i;
      EXPECT_LT(error.luminance, 0.01) << "view " << i;
    }
  }
}

// Three wavelengths shown as RGB miss the same sky's chromaticity by more than the target (by
// 0.015-0.02 here: the solar spectrum's colour is not its values at 680, 550 and 440 nm), which
// is what the spectral mode is for. If the rgb mode ever met the target, this would tell.
TEST_F(SpectralTables, ThreeWavelengthsMissTheChromaticity) {
  ViewsCompared c = CompareViews(ColourMode::kRgb);
  for (size_t i = 0; i < kViews.size(); ++i)
    EXPECT_GT(Compare(c.tables[i].sky_radiance, c.reference[i].sky_radiance).chromaticity, 0.005) << "view " << i;
}

}  // namespace
}  // namespace aerial::testing
