// `aerial envmap`: the lat-long map holds, at each texel, what `aerial probe` gives along the
// texel's direction (the layout written here from its documented convention, not from the code);
// below the horizon the lit ground through the air; the cube map's texels are where OpenEXR's
// cube functions put their directions; the sun's disc, when drawn, carries the irradiance the
// file's attributes state, at the texel of the sun's direction; OpenImageIO reads the files.
#include <gtest/gtest.h>

#include <OpenEXR/ImfEnvmap.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>
#include <utility>
#include <vector>

#include "aerial/envmap/environment_map.h"
#include "aerial/precompute/spectral_precompute.h"
#include "aerial/probe/table_probe.h"
#include "command_run.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

constexpr double kDegree = M_PI / 180.0;

// The spectral tables (the command's default colour) that the VDB tests use too.
const AtmosphereTables& SpectralTables() {
  PrecomputeOptions options = PrecomputeOptions::Small();
  options.orders = 1;
  options.close_series = false;
  options.colour = ColourMode::kSpectral;
  return CachedTables(options);
}

// The probe's query for a direction (scene frame) from a point `altitude_m` up, under `sun`.
ProbeQuery QueryAlong(const glm::dvec3& direction, double altitude_m, const Sun& sun, double planet_radius_m) {
  const glm::dvec3 toward_sun = sun.Direction();
  return {{planet_radius_m + altitude_m, direction.z, toward_sun.z, glm::dot(direction, toward_sun)}};
}

// What the map should hold along each of `directions`: the probe's sky radiance (no sun disc)
// and, where the direction meets the planet, the ground lit by the sun and the sky (Lambertian, the
// atmosphere's albedo, the probe's irradiances at the ground point) times the probe's
// transmittance to it. The probe answers all the directions in one batch, the ground points in
// another: each call of it builds its compute pipeline.
std::vector<glm::dvec3> Expected(const AtmosphereTables& tables, const std::vector<glm::dvec3>& directions,
                                 double altitude_m, const Sun& sun) {
  const double radius = tables.atmosphere().bottom_radius_m, r = radius + altitude_m;
  std::vector<ProbeQuery> along;
  for (const glm::dvec3& direction : directions) along.push_back(QueryAlong(direction, altitude_m, sun, radius));
  const std::vector<ProbeResult> sky = ProbeTables(tables, along);
  std::vector<glm::dvec3> radiance;
  std::vector<ProbeQuery> at_ground;
  std::vector<size_t> seeing_ground;
  for (size_t i = 0; i < directions.size(); ++i) {
    radiance.emplace_back(sky[i].sky_radiance[0], sky[i].sky_radiance[1], sky[i].sky_radiance[2]);
    const glm::dvec3& direction = directions[i];
    const double mu = direction.z, discriminant = r * r * (mu * mu - 1.0) + radius * radius;
    if (mu < 0.0 && discriminant >= 0.0) {
      const double distance = -r * mu - std::sqrt(discriminant);
      const glm::dvec3 ground = glm::dvec3(0, 0, r) + distance * direction;  // from the planet's centre
      const glm::dvec3 up = glm::normalize(ground);
      at_ground.push_back({{radius, 1.0, glm::dot(up, sun.Direction()), 0.0}});
      seeing_ground.push_back(i);
    }
  }
  const std::vector<ProbeResult> lit = ProbeTables(tables, at_ground);
  const Spectrum albedo = ShaderAtmosphere(tables.atmosphere(), tables.options()).ground_albedo;
  for (size_t g = 0; g < seeing_ground.size(); ++g) {
    const size_t i = seeing_ground[g];
    for (int c = 0; c < 3; ++c)
      radiance[i][c] += sky[i].transmittance[c] * albedo[c] / M_PI * (lit[g].sun_irradiance[c] + lit[g].sky_irradiance[c]);
  }
  return radiance;
}

// The lat-long convention of the docs: texel (x, y) at zenith 180 (y + 0.5) / H and compass
// azimuth 360 (x + 0.5) / W - 90 degrees (the centre column east).
glm::dvec3 LatLongDirection(int x, int y, int width, int height) {
  const double zenith = M_PI * (y + 0.5) / height, azimuth = 2.0 * M_PI * (x + 0.5) / width - 0.5 * M_PI;
  return {std::sin(zenith) * std::sin(azimuth), std::sin(zenith) * std::cos(azimuth), std::cos(zenith)};
}

class Envmap : public GpuTest {};

// 100 random texels, above and below the horizon, within 0.5% per channel of the probe (the
// same lookups in float; the texel's direction passes through float once more). The sun's
// irradiance it states is the probe's on a horizontal surface divided by the sun's cosine.
TEST_F(Envmap, LatLongAgreesWithTheProbeAlongRandomDirections) {
  const AtmosphereTables& tables = SpectralTables();
  const EnvironmentMapOptions options{.size = 64, .altitude_m = 500.0, .sun = {.zenith_deg = 40.0, .azimuth_deg = 120.0}};
  const EnvironmentMap map = RenderEnvironmentMap(tables, options);
  ASSERT_EQ(map.image.width, 128);
  ASSERT_EQ(map.image.height, 64);
  std::mt19937 random(68);
  std::vector<std::pair<int, int>> texels;
  std::vector<glm::dvec3> directions;
  for (int n = 0; n < 100; ++n) {
    const int x = int(random() % 128), y = int(random() % 64);
    texels.emplace_back(x, y);
    directions.push_back(LatLongDirection(x, y, 128, 64));
  }
  const std::vector<glm::dvec3> expected_radiance = Expected(tables, directions, options.altitude_m, options.sun);
  double worst = 0.0;
  int below = 0;
  for (size_t n = 0; n < texels.size(); ++n) {
    const auto [x, y] = texels[n];
    const glm::dvec3& expected = expected_radiance[n];
    below += directions[n].z < 0.0;
    for (int c = 0; c < 3; ++c) {
      const double error = std::abs(map.image.pixel(x, y)[c] / expected[c] - 1.0);
      worst = std::max(worst, error);
      EXPECT_LT(error, 0.005) << "texel " << x << ", " << y << " channel " << c;
    }
    EXPECT_EQ(map.image.pixel(x, y)[3], 1.0f);
  }
  const ProbeQuery straight_up = QueryAlong({0, 0, 1}, options.altitude_m, options.sun, tables.atmosphere().bottom_radius_m);
  const ProbeResult sun = ProbeTables(tables, std::span(&straight_up, 1)).front();
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(map.sun_irradiance[c], sun.sun_irradiance[c] / std::cos(40.0 * kDegree), 0.005 * map.sun_irradiance[c]);
  std::printf("lat-long map against the probe: worst relative error %.2e over 100 texels (%d below the horizon)\n",
              worst, below);
  EXPECT_GT(below, 20);
  EXPECT_LT(below, 80);
}

// Each cube texel holds the probe's value along the direction OpenEXR's cube map gives that
// texel (Imf::CubeMap, in the frame X north, Y up, Z east), on a sample of every face.
TEST_F(Envmap, CubeTexelsLookWhereOpenExrSays) {
  const AtmosphereTables& tables = SpectralTables();
  const EnvironmentMapOptions options{
      .layout = EnvironmentLayout::kCube, .size = 16, .altitude_m = 10.0, .sun = {.zenith_deg = 60.0, .azimuth_deg = 250.0}};
  const EnvironmentMap map = RenderEnvironmentMap(tables, options);
  ASSERT_EQ(map.image.width, 16);
  ASSERT_EQ(map.image.height, 96);
  const Imath::Box2i window(Imath::V2i(0, 0), Imath::V2i(15, 95));
  struct Sample {
    int face, i, j;
    Imath::V2f pixel;
  };
  std::vector<Sample> samples;
  std::vector<glm::dvec3> directions;
  for (int face = 0; face < 6; ++face)
    for (int j : {0, 5, 15})
      for (int i : {0, 9, 15}) {
        const Imath::V2f in_face{float(i), float(j)};
        samples.push_back({face, i, j, Imf::CubeMap::pixelPosition(Imf::CubeMapFace(face), window, in_face)});
        const Imath::V3f exr = Imf::CubeMap::direction(Imf::CubeMapFace(face), window, in_face);
        directions.push_back(glm::normalize(glm::dvec3(exr.z, exr.x, exr.y)));  // east, north, up
      }
  const std::vector<glm::dvec3> expected = Expected(tables, directions, options.altitude_m, options.sun);
  double worst = 0.0;
  for (size_t n = 0; n < samples.size(); ++n) {
    const Sample& s = samples[n];
    const float* read = map.image.pixel(int(std::lround(s.pixel.x)), int(std::lround(s.pixel.y)));
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(read[c] / expected[n][c] - 1.0));
      EXPECT_LT(std::abs(read[c] / expected[n][c] - 1.0), 0.005) << "face " << s.face << " texel " << s.i << ", " << s.j;
    }
  }
  std::printf("cube map against the probe along OpenEXR's directions: worst relative error %.2e\n", worst);
}

// With the disc drawn, the map's excess over the disc-less map, summed over the texels' solid
// angles, is the sun's irradiance the map states (the disc is 3 texels across at this size,
// texels it touches sampled 16 x 16: within 1.5%), and it lies at the texel of the sun's
// direction by the documented convention: azimuth 90 (east) in the centre column, zenith 60
// degrees a third of the way down.
TEST_F(Envmap, SunDiscHoldsTheStatedIrradianceWhereTheSunIs) {
  const AtmosphereTables& tables = SmallTables();
  EnvironmentMapOptions options{.size = 512, .sun = {.zenith_deg = 60.0, .azimuth_deg = 90.0}};
  const EnvironmentMap without = RenderEnvironmentMap(tables, options);
  options.sun_disc = true;
  const EnvironmentMap with = RenderEnvironmentMap(tables, options);
  const int width = with.image.width, height = with.image.height;
  glm::dvec3 irradiance(0.0);
  double brightest = 0.0;
  int brightest_x = -1, brightest_y = -1;
  for (int y = 0; y < height; ++y) {
    const double solid_angle = 2.0 * M_PI / width * (std::cos(M_PI * y / height) - std::cos(M_PI * (y + 1) / height));
    for (int x = 0; x < width; ++x) {
      const float* a = with.image.pixel(x, y);
      const float* b = without.image.pixel(x, y);
      for (int c = 0; c < 3; ++c) irradiance[c] += (double(a[c]) - b[c]) * solid_angle;
      if (a[1] - b[1] > brightest) {
        brightest = a[1] - b[1];
        brightest_x = x;
        brightest_y = y;
      }
    }
  }
  std::printf("sun disc in the map: irradiance %.4g %.4g %.4g, stated %.4g %.4g %.4g W/m^2/nm; brightest texel %d, %d\n",
              irradiance[0], irradiance[1], irradiance[2], with.sun_irradiance[0], with.sun_irradiance[1],
              with.sun_irradiance[2], brightest_x, brightest_y);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(irradiance[c], with.sun_irradiance[c], 0.015 * with.sun_irradiance[c]);
  EXPECT_NEAR(brightest_x, width / 2, 1);
  EXPECT_NEAR(brightest_y, height / 3, 1);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(with.sun_irradiance[c], without.sun_irradiance[c]);
}

class EnvmapCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("aerial_envmap_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

// The command's files as OpenEXR's own reader and OpenImageIO (Debian's python3-openimageio, a
// reader sharing no code with aerial) see them: 64 x 32 and 16 x 96 float RGBA, the envmap
// attribute, and the sun of the date (SPA's test case: zenith 50.13 degrees geometric, azimuth
// 194.34) in the attributes.
TEST_F(EnvmapCommand, WritesLatLongAndCubeFilesThatOpenImageIoReads) {
  const std::string out = (dir_ / "sky.exr").string(), cube = (dir_ / "cube.exr").string();
  CommandRun run = RunAerial("envmap --small-tables --quiet --width 64 --height 32 --date 2003-10-17 --time 12:30:30 "
                             "--time-zone -07:00 --latitude-deg 39.742476 --longitude-deg -105.1786 --out " + out +
                             " --cube-map " + cube);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  Imf::InputFile file(out.c_str());
  const Imf::Header& header = file.header();
  EXPECT_EQ(header.dataWindow().max.x, 63);
  EXPECT_EQ(header.dataWindow().max.y, 31);
  ASSERT_TRUE(Imf::hasEnvmap(header));
  EXPECT_EQ(Imf::envmap(header), Imf::ENVMAP_LATLONG);
  EXPECT_NEAR(header.typedAttribute<Imf::FloatAttribute>("aerial:sun_zenith_deg").value(), 50.128, 0.001);
  EXPECT_NEAR(header.typedAttribute<Imf::FloatAttribute>("aerial:sun_azimuth_deg").value(), 194.340, 0.001);
  const Imath::V3f sun = header.typedAttribute<Imf::V3fAttribute>("aerial:sun_irradiance").value();
  EXPECT_GT(sun.x, 0.0f);
  EXPECT_GT(sun.z, 0.0f);
  Imf::InputFile cube_file(cube.c_str());
  EXPECT_EQ(Imf::envmap(cube_file.header()), Imf::ENVMAP_CUBE);
  EXPECT_EQ(cube_file.header().dataWindow().max.y, 95);

  if (std::system("/usr/bin/python3 -c 'import OpenImageIO' 2>/dev/null") != 0)
    GTEST_SKIP() << "/usr/bin/python3 has no OpenImageIO (Debian's python3-openimageio, in tools/setup.sh)";
  std::ofstream(dir_ / "read.py") << R"(
import sys, OpenImageIO as oiio
for path in sys.argv[1:]:
    image = oiio.ImageInput.open(path)
    spec = image.spec()
    pixels = image.read_image(oiio.FLOAT)
    print(spec.width, spec.height, ",".join(spec.channelnames), spec.format,
          spec.getattribute("aerial:sun_disc").split(":")[0], int(pixels.min() > 0))
    image.close()
)";
  const std::string read = (dir_ / "read.txt").string();
  ASSERT_EQ(std::system(("/usr/bin/python3 " + (dir_ / "read.py").string() + " " + out + " " + cube + " > " + read).c_str()),
            0);
  std::ifstream in(read);
  std::string lat_long, cube_line;
  std::getline(in, lat_long);
  std::getline(in, cube_line);
  EXPECT_EQ(lat_long, "64 32 R,G,B,A float left out 1");
  EXPECT_EQ(cube_line, "16 96 R,G,B,A float left out 1");
}

// Bad input stops the command before any work, naming the value.
TEST_F(EnvmapCommand, BadInputIsNamed) {
  const std::string out = " --out " + (dir_ / "sky.exr").string();
  const std::string place = " --time 12:00 --time-zone UTC --latitude-deg 45 --longitude-deg 5";
  struct Case {
    std::string arguments, message;
  };
  const Case cases[] = {
      {"envmap --date 2023-02-29" + place + out, "--date = 2023-02-29 is invalid"},
      {"envmap --date 2023-06-01 --time 12:00 --time-zone UTC --latitude-deg 91 --longitude-deg 5" + out,
       "--latitude-deg = 91 is invalid"},
      {"envmap --date 2023-06-01 --time 12:00 --time-zone Europe/Atlantis --latitude-deg 45 --longitude-deg 5" + out,
       "--time-zone = Europe/Atlantis is invalid"},
      {"envmap --date 2023-06-01" + place + " --sun-zenith-deg 30" + out, "--date = 2023-06-01 is invalid; expected no --sun-zenith-deg"},
      {"envmap --date 2023-06-01 --time 12:00 --latitude-deg 45 --longitude-deg 5" + out, "--time-zone = (not given)"},
      {"envmap --width 100 --height 100" + out, "--width/--height = 100x100 is invalid"},
      {"envmap --altitude-m -1" + out, "--altitude-m = -1 is invalid"},
      {"envmap" + out + " --cube-map " + (dir_ / "sky.exr").string(), "a file other than --out"},
      {"render --date 2024-03-31 --time 02:30 --time-zone Europe/Paris --latitude-deg 48.85 --longitude-deg 2.35 --out " +
           (dir_ / "x.png").string(),
       "--time = 02:30 is invalid"},
      {"export-vdb --date 2023-06-01" + place + " --sun-azimuth-deg 10 --out " + (dir_ / "x.vdb").string(),
       "--date = 2023-06-01 is invalid"},
  };
  for (const Case& c : cases) {
    CommandRun run = RunAerial(c.arguments);
    EXPECT_EQ(run.exit_code, 1) << c.arguments << "\n" << run.err;
    EXPECT_NE(run.err.find(c.message), std::string::npos) << c.arguments << "\n" << run.err;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

}  // namespace
}  // namespace aerial::testing
