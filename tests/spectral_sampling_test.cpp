// How many wavelengths the spectral mode needs: the sunlight on the ground, computed by the CPU
// reference at N wavelengths and converted to colour, against 48 wavelengths (one per 10 nm of the
// solar and ozone data).
#include <gtest/gtest.h>

#include <cmath>

#include "aerial/reference/reference.h"
#include "aerial/spectrum/spectral_atmosphere.h"

namespace aerial {
namespace {

// XYZ of the direct sunlight on a horizontal ground under a sun at this zenith angle.
Spectrum SunlightXyz(int wavelengths, double sun_zenith_deg) {
  spectrum::SpectralSampling sampling(wavelengths);
  spectrum::SpectralAtmosphere earth(AtmosphereParameters::Earth());
  std::vector<double> values;
  for (int g = 0; g < sampling.groups(); ++g) {
    AtmosphereParameters group = earth.At(sampling.Group(g));
    reference::Reference model(group);
    Spectrum e = model.ComputeDirectIrradiance(group.bottom_radius_m, std::cos(sun_zenith_deg * M_PI / 180.0));
    values.insert(values.end(), e.begin(), e.end());
  }
  return sampling.Xyz(values);
}

// 12 wavelengths meet the daylight target of du'v' <= 0.003 (issue 40) at every sun elevation
// down to 85 degrees, and 6 do not: the sun's colour needs the spectrum sampled every 40 nm.
TEST(SpectralSampling, TwelveWavelengthsGiveTheSunlightsColourAndSixDoNot) {
  for (double zenith : {0.0, 60.0, 85.0}) {
    Spectrum fine = SunlightXyz(48, zenith);
    EXPECT_LT(spectrum::ChromaticityDistance(SunlightXyz(12, zenith), fine), 0.003) << zenith;
    EXPECT_NEAR(SunlightXyz(12, zenith)[1] / fine[1], 1.0, 0.01) << zenith;
    EXPECT_GT(spectrum::ChromaticityDistance(SunlightXyz(6, zenith), fine), 0.003) << zenith;
  }
}

}  // namespace
}  // namespace aerial
