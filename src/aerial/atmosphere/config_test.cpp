#include "aerial/atmosphere/config.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>

#include "aerial/error.h"
#include "aerial/spectrum/spectral_data.h"

#ifndef AERIAL_SOURCE_DIR
#define AERIAL_SOURCE_DIR "."
#endif

namespace aerial {
namespace {

const std::filesystem::path kExamples =
    std::filesystem::path(AERIAL_SOURCE_DIR) / "examples/atmospheres";

// Exact comparison of every field: the config must reproduce doubles bit for bit (the cache key
// is a hash of them), so no tolerance anywhere here.
void ExpectSameLayer(const DensityProfileLayer& a, const DensityProfileLayer& b,
                     const std::string& what) {
  EXPECT_EQ(a.width_m, b.width_m) << what;
  EXPECT_EQ(a.exp_term, b.exp_term) << what;
  EXPECT_EQ(a.exp_scale_per_m, b.exp_scale_per_m) << what;
  EXPECT_EQ(a.linear_term_per_m, b.linear_term_per_m) << what;
  EXPECT_EQ(a.constant_term, b.constant_term) << what;
}

void ExpectSameProfile(const DensityProfile& a, const DensityProfile& b, const std::string& what) {
  ExpectSameLayer(a.layers[0], b.layers[0], what + ".layers[0]");
  ExpectSameLayer(a.layers[1], b.layers[1], what + ".layers[1]");
}

void ExpectSameAtmosphere(const AtmosphereParameters& a, const AtmosphereParameters& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.wavelengths_nm, b.wavelengths_nm);
  EXPECT_EQ(a.solar_irradiance, b.solar_irradiance);
  EXPECT_EQ(a.sun_angular_radius_rad, b.sun_angular_radius_rad);
  EXPECT_EQ(a.bottom_radius_m, b.bottom_radius_m);
  EXPECT_EQ(a.top_radius_m, b.top_radius_m);
  ExpectSameProfile(a.rayleigh_density, b.rayleigh_density, "rayleigh_density");
  EXPECT_EQ(a.rayleigh_scattering, b.rayleigh_scattering);
  ExpectSameProfile(a.mie_density, b.mie_density, "mie_density");
  EXPECT_EQ(a.mie_scattering, b.mie_scattering);
  EXPECT_EQ(a.mie_extinction, b.mie_extinction);
  EXPECT_EQ(a.mie_phase_g, b.mie_phase_g);
  ExpectSameProfile(a.absorption_density, b.absorption_density, "absorption_density");
  EXPECT_EQ(a.absorption_extinction, b.absorption_extinction);
  EXPECT_EQ(a.ground_albedo, b.ground_albedo);
  EXPECT_EQ(a.mu_s_min, b.mu_s_min);
  EXPECT_EQ(a.Hash(), b.Hash());
}

TEST(AtmosphereConfig, EarthExampleEqualsBuiltInEarth) {
  ExpectSameAtmosphere(LoadAtmosphereFile(kExamples / "earth.toml"), AtmosphereParameters::Earth());
}

TEST(AtmosphereConfig, EmptyFileIsEarth) {
  ExpectSameAtmosphere(ParseAtmosphereToml("", "empty.toml"), AtmosphereParameters::Earth());
}

TEST(AtmosphereConfig, EveryExampleLoadsAndValidates) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kExamples)) {
    if (entry.path().extension() != ".toml") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(LoadAtmosphereFile(entry.path()));
    ++count;
  }
  EXPECT_GE(count, 3);
}

TEST(AtmosphereConfig, PartialOverrideKeepsOtherEarthValues) {
  AtmosphereParameters a = ParseAtmosphereToml(
      "name = \"thick\"\ntop_radius_m = 6500000  # an integer is a number too\n"
      "[mie]\nphase_g = 0.7\n",
      "partial.toml");
  AtmosphereParameters expected = AtmosphereParameters::Earth();
  expected.name = "thick";
  expected.top_radius_m = 6500e3;
  expected.mie_phase_g = 0.7;
  ExpectSameAtmosphere(a, expected);
}

TEST(AtmosphereConfig, OneDensityLayerAppliesEverywhere) {
  AtmosphereParameters a = ParseAtmosphereToml(
      "[rayleigh]\ndensity = [ { exp_term = 1.0, exp_scale_per_m = -1e-4 } ]\n", "one.toml");
  ExpectSameLayer(a.rayleigh_density.layers[0], DensityProfileLayer{}, "layers[0] is zero");
  ExpectSameLayer(a.rayleigh_density.layers[1], DensityProfileLayer{0.0, 1.0, -1e-4, 0.0, 0.0},
                  "layers[1] is the given layer, missing keys 0");
}

TEST(AtmosphereConfig, MaxSunZenithAnglesGiveExactCosines) {
  EXPECT_EQ(MuSMinFromMaxSunZenithDeg(90.0), 0.0);
  EXPECT_EQ(MuSMinFromMaxSunZenithDeg(120.0), -0.5);
  EXPECT_EQ(MuSMinFromMaxSunZenithDeg(180.0), -1.0);
  EXPECT_EQ(MaxSunZenithDegFromMuSMin(-0.5), 120.0);
  EXPECT_EQ(ParseAtmosphereToml("max_sun_zenith_deg = 102", "x.toml").mu_s_min,
            MuSMinFromMaxSunZenithDeg(102.0));
}

// Awkward doubles (non-terminating binary fractions, a denormal, an odd angle) and
// a name that needs escaping must all survive the trip unchanged.
TEST(AtmosphereConfig, ToTomlRoundTripsExactly) {
  AtmosphereParameters a = AtmosphereParameters::Earth();
  a.name = "odd \"name\" \\ with\ttab";
  a.wavelengths_nm = {1400.1 / 3.0, 0.1 + 0.2 + 500.0, 360.0};
  a.solar_irradiance = {1.0 / 3.0, 5e-324, 999.99999999999989};
  a.rayleigh_density.layers[0] = {1234.5678, 0.3, -1.0 / 7000.0, 1e-9, 0.1};
  a.mie_phase_g = -0.9999999;
  a.mu_s_min = MuSMinFromMaxSunZenithDeg(97.123456789);
  for (const AtmosphereParameters& p : {AtmosphereParameters::Earth(), a}) {
    std::string text = ToToml(p);
    SCOPED_TRACE(text);
    ExpectSameAtmosphere(ParseAtmosphereToml(text, "roundtrip.toml"), p);
  }
}

TEST(AtmosphereConfig, MissingFileErrorNamesPath) {
  try {
    LoadAtmosphereFile("/nonexistent/dir/sky.toml");
    FAIL() << "expected aerial::Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.value(), "/nonexistent/dir/sky.toml");
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/sky.toml"), std::string::npos);
  }
}

TEST(AtmosphereConfig, SyntaxErrorGivesLineAndColumn) {
  try {
    ParseAtmosphereToml("name = \"x\"\nbottom_radius_m = = 3\n", "broken.toml");
    FAIL() << "expected aerial::Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "TOML syntax");
    EXPECT_TRUE(std::regex_match(e.where(), std::regex("broken\\.toml:2:[0-9]+"))) << e.where();
  }
}

TEST(AtmosphereConfig, ValidateNamesFieldOfParametersMadeInCode) {
  AtmosphereParameters a = AtmosphereParameters::Earth();
  a.mie_phase_g = 1.0;
  try {
    Validate(a);
    FAIL() << "expected aerial::Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "mie.phase_g");
    EXPECT_EQ(e.value(), "1.0");
  }
}

// Values finite as doubles but inf as the floats the shaders receive: the
// message names the key and the value.
TEST(AtmosphereConfig, ValuesBeyondFloatAreNamedWithTheirValue) {
  for (auto [text, message] :
       {std::pair{"solar_irradiance = [1e300, 1.0, 1.0]", "solar_irradiance[0] = 1e+300 is invalid"},
        std::pair{"[rayleigh]\nscattering = [1e300, 1e-5, 1e-5]", "rayleigh.scattering[0] = 1e+300 is invalid"}}) {
    try {
      ParseAtmosphereToml(text, "snippet.toml");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

// The bounds a message states are in the range, as float: 0.1 must not be refused as
// 0.100000001 by a message allowing [0.0, 0.1].
TEST(AtmosphereConfig, StatedBoundsAreAccepted) {
  EXPECT_NO_THROW(ParseAtmosphereToml("[rayleigh]\nscattering = [0.1, 0.1, 0.1]", "snippet.toml"));
  EXPECT_NO_THROW(ParseAtmosphereToml("sun_angular_radius_rad = 0.1", "snippet.toml"));
}

// The wavelength range is where every spectrum the spectral precompute reads is tabulated: a data
// file that grows or shrinks must move the range with it.
TEST(AtmosphereConfig, WavelengthRangeIsWhereTheSpectralDataAre) {
  const spectrum::TabulatedSpectrum* data[] = {&spectrum::SolarIrradiance(), &spectrum::OzoneCrossSection(),
                                                &spectrum::Cie1931ColourMatching()[1]};
  double first = 0.0, last = 1e9;
  for (const spectrum::TabulatedSpectrum* d : data) {
    first = std::max(first, d->wavelengths_nm.front());
    last = std::min(last, d->wavelengths_nm.back());
  }
  EXPECT_EQ(kMinWavelengthNm, first);
  EXPECT_EQ(kMaxWavelengthNm, last);
  EXPECT_NO_THROW(ParseAtmosphereToml("wavelengths_nm = [830.0, 550.0, 360.0]", "snippet.toml"));
  // One dark channel is a valid sun (its white balance: tone_map_test.cpp).
  EXPECT_NO_THROW(ParseAtmosphereToml("solar_irradiance = [1.0, 0.0, 1.0]", "snippet.toml"));
}

struct BadSnippet {
  const char* toml;
  const char* field;  // the dotted key the error must name.
};

// Every invalid input is rejected with an Error that names the offending key and points at its
// line in the file.
TEST(AtmosphereConfig, EveryInvalidFieldIsNamedInTheError) {
  const BadSnippet kBad[] = {
      {"bottom_radius_m = 0.0", "bottom_radius_m"},
      {"bottom_radius_m = -6360000.0", "bottom_radius_m"},
      {"bottom_radius_m = inf", "bottom_radius_m"},
      {"bottom_radius_m = \"6360 km\"", "bottom_radius_m"},
      {"bottom_radius_m = true", "bottom_radius_m"},
      {"top_radius_m = 0.0", "top_radius_m"},
      {"top_radius_m = 6000000.0", "top_radius_m"},  // below the ground.
      {"top_radius_m = 7400000.0", "top_radius_m"},  // 1040 km thick.
      {"top_radius_m = nan", "top_radius_m"},
      {"wavelengths_nm = [680.0, 550.0, 200.0]", "wavelengths_nm[2]"},
      {"wavelengths_nm = [nan, 550.0, 440.0]", "wavelengths_nm[0]"},
      // Within 300-1000 nm, which the check allowed before, but outside the spectral data: the
      // spectral sun was zero and the render failed after its precompute.
      {"wavelengths_nm = [680.0, 550.0, 350.0]", "wavelengths_nm[2]"},
      {"wavelengths_nm = [900.0, 550.0, 440.0]", "wavelengths_nm[0]"},
      {"solar_irradiance = [0.0, 0.0, 0.0]", "solar_irradiance"},
      {"wavelengths_nm = [680.0, 550.0]", "wavelengths_nm"},
      {"solar_irradiance = [1.0, -1.0, 1.0]", "solar_irradiance[1]"},
      {"solar_irradiance = [1.0, inf, 1.0]", "solar_irradiance[1]"},
      // Finite doubles that become inf or 0 in float, or leave the physical range.
      {"solar_irradiance = [1e300, 1.0, 1.0]", "solar_irradiance[0]"},
      {"solar_irradiance = [1.0, 1.0, 1e39]", "solar_irradiance[2]"},
      {"solar_irradiance = [1.0, 1.0, 1001.0]", "solar_irradiance[2]"},
      {"sun_angular_radius_rad = 1e-300", "sun_angular_radius_rad"},
      {"sun_angular_radius_rad = 5e-5", "sun_angular_radius_rad"},
      {"bottom_radius_m = 1e300", "bottom_radius_m"},
      {"bottom_radius_m = 1000.0", "bottom_radius_m"},
      {"top_radius_m = 6360000.1", "top_radius_m"},  // the same float as the bottom.
      {"[rayleigh]\nscattering = [1e-6, 1e300, 3e-6]", "rayleigh.scattering[1]"},
      {"[rayleigh]\nscattering = [1e-6, 2e-6, 0.5]", "rayleigh.scattering[2]"},
      {"[mie]\nextinction = [1e300, 1e-5, 1e-5]", "mie.extinction[0]"},
      {"[ozone]\nabsorption = [1e300, 0.0, 0.0]", "ozone.absorption[0]"},
      {"[mie]\nphase_g = 0.99999999999", "mie.phase_g"},  // 1 in float.
      {"[rayleigh]\ndensity = [ { exp_term = 1e300 } ]", "rayleigh.density[0].exp_term"},
      {"[rayleigh]\ndensity = [ { exp_term = 1.0, exp_scale_per_m = 0.01 } ]",
       "rayleigh.density[0].exp_scale_per_m"},  // e^600 at the top.
      {"[rayleigh]\ndensity = [ { exp_term = 0.0, exp_scale_per_m = 0.01 } ]",
       "rayleigh.density[0].exp_scale_per_m"},  // 0 * inf in float.
      {"[rayleigh]\ndensity = [ { linear_term_per_m = 1e30 } ]", "rayleigh.density[0].linear_term_per_m"},
      {"[rayleigh]\ndensity = [ { constant_term = 1e39 } ]", "rayleigh.density[0].constant_term"},
      {"sun_angular_radius_rad = 0.0", "sun_angular_radius_rad"},
      {"sun_angular_radius_rad = 0.2", "sun_angular_radius_rad"},
      {"ground_albedo = [0.1, 2.0, 0.1]", "ground_albedo[1]"},
      {"ground_albedo = [-0.1, 0.1, 0.1]", "ground_albedo[0]"},
      {"max_sun_zenith_deg = 45.0", "max_sun_zenith_deg"},
      {"max_sun_zenith_deg = 181", "max_sun_zenith_deg"},
      {"max_sun_zenith_deg = nan", "max_sun_zenith_deg"},
      {"name = 3", "name"},
      {"colour = \"blue\"", "colour"},
      {"rayleigh = 3.0", "rayleigh"},
      {"[rayleigh]\nscattering = [-1e-6, 0.0, 0.0]", "rayleigh.scattering[0]"},
      {"[rayleigh]\nscattering = [1e-6, 2e-6]", "rayleigh.scattering"},
      {"[rayleigh]\nscattering = [1e-6, 2e-6, 3e-6, 4e-6]", "rayleigh.scattering"},
      {"[rayleigh]\nscattering = 1e-6", "rayleigh.scattering"},
      {"[rayleigh]\nscattering = [1e-6, \"x\", 3e-6]", "rayleigh.scattering[1]"},
      {"[rayleigh]\nscattering = [1e-6, 2e-6, inf]", "rayleigh.scattering[2]"},
      {"[rayleigh]\nscatering = [1e-6, 2e-6, 3e-6]", "rayleigh.scatering"},
      {"[rayleigh.extra]\nx = 1", "rayleigh.extra"},
      {"[mie]\nphase_g = 1.0", "mie.phase_g"},
      {"[mie]\nphase_g = -1.0", "mie.phase_g"},
      {"[mie]\nphase_g = nan", "mie.phase_g"},
      {"[mie]\nphase_g = \"0.8\"", "mie.phase_g"},
      {"[mie]\nphase = 0.8", "mie.phase"},
      {"[mie]\nscattering = [-1e-6, 0.0, 0.0]", "mie.scattering[0]"},
      {"[mie]\nextinction = [1e-6, 1e-5, 1e-5]", "mie.extinction[0]"},  // < scattering 3.996e-6.
      {"[mie]\nextinction = [1e-5, -inf, 1e-5]", "mie.extinction[1]"},
      {"[mie]\ndensity = [ { width_m = 0.0, exp_trm = 1.0 } ]", "mie.density[0].exp_trm"},
      {"[mie]\ndensity = [ {}, {}, {} ]", "mie.density"},
      {"[mie]\ndensity = []", "mie.density"},
      {"[mie]\ndensity = { exp_term = 1.0 }", "mie.density"},
      {"[mie]\ndensity = [ 1.0 ]", "mie.density[0]"},
      {"[mie]\ndensity = [ { width_m = -1.0, exp_term = 1.0 }, {} ]", "mie.density[0].width_m"},
      {"[mie]\ndensity = [ { exp_term = nan } ]", "mie.density[0].exp_term"},
      {"[mie]\ndensity = [ { exp_scale_per_m = \"fast\" } ]", "mie.density[0].exp_scale_per_m"},
      {"[ozone]\nabsorption = [0.0, -1e-7, 0.0]", "ozone.absorption[1]"},
      {"[ozone]\ndensity = [ { width_m = 25000.0, constant_term = inf }, {} ]",
       "ozone.density[0].constant_term"},
      {"[ozone]\ndensity = [ {}, { linear_term_per_m = 1.0, units = 2 } ]",
       "ozone.density[1].units"},
  };
  for (const BadSnippet& bad : kBad) {
    SCOPED_TRACE(bad.toml);
    try {
      ParseAtmosphereToml(bad.toml, "snippet.toml");
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.field(), bad.field) << e.what();
      EXPECT_NE(std::string(e.what()).find(bad.field), std::string::npos) << e.what();
      EXPECT_FALSE(e.allowed().empty()) << e.what();
      EXPECT_TRUE(std::regex_match(e.where(), std::regex("snippet\\.toml:[0-9]+:[0-9]+")))
          << e.what();
    }
  }
}

}  // namespace
}  // namespace aerial
