#include "aerial/spectrum/spectral_data.h"

#include <gtest/gtest.h>

#include "aerial/atmosphere.h"
#include "aerial/error.h"

namespace aerial::spectrum {
namespace {

// CIE 015: the integral of y-bar over 360-830 nm is 106.857 nm (1 nm table: 106.856895); the 5 nm
// table's trapezoid gives the same to 2e-6. x-bar and z-bar integrate to the same within 0.05%,
// which is what puts the equal-energy white at x = y = 1/3.
TEST(SpectralData, ColourMatchingFunctionsHaveTheirKnownIntegrals) {
  const auto& cmf = Cie1931ColourMatching();
  EXPECT_NEAR(YBarIntegralNm(), 106.857, 0.001);
  EXPECT_NEAR(cmf[0].Integral() / YBarIntegralNm(), 1.0, 5e-4);
  EXPECT_NEAR(cmf[2].Integral() / YBarIntegralNm(), 1.0, 5e-4);
  EXPECT_EQ(cmf[1].At(555.0), 1.0);  // y-bar peaks at 1 at 555 nm by definition
  EXPECT_EQ(cmf[1].At(300.0), 0.0);  // zero outside the table
}

// The built-in three-wavelength Earth (AtmosphereParameters::Earth, Bruneton 2017's values at 680,
// 550 and 440 nm) comes from the same measurements: the solar irradiance exactly, the ozone
// absorption as 300 DU over the 15 km tent times the cross-section (to the 4 digits Earth keeps).
TEST(SpectralData, AgreeWithTheThreeWavelengthEarth) {
  AtmosphereParameters earth = AtmosphereParameters::Earth();
  const double ozone_peak_density = 300.0 * kDobsonUnit / 15000.0;
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(SolarIrradiance().At(earth.wavelengths_nm[i]), earth.solar_irradiance[i]);
    EXPECT_NEAR(ozone_peak_density * OzoneCrossSection().At(earth.wavelengths_nm[i]) / earth.absorption_extinction[i],
                1.0, 1e-3);
  }
  // The Chappuis band peaks near 600 nm (5.0e-25 m^2 at 600 nm).
  EXPECT_NEAR(OzoneCrossSection().At(600.0), 5.019e-25, 1e-28);
}

TEST(SpectralData, MalformedRowsAreNamed) {
  EXPECT_THROW(ReadCsvColumn("# c\nwavelength,value\n360,1\n350,2\n", 1, "t.csv"), Error);
  try {
    ReadCsvColumn("wavelength,value\n360,x\n", 1, "t.csv");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("t.csv line 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace aerial::spectrum
