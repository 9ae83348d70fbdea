// CTest label "sanitizer": the public API's seams: run under the sanitizers too.
// The public API (include/aerial/) as a renderer that embeds aerial uses it: its own command
// buffer, aerial's froxel volume for its camera, the tables as images it binds.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "aerial/aerial.h"
#include "aerial/api/impl.h"
#include "aerial/render/renderer.h"
#include "gpu_fixture.h"
#include "pseudo_terminal.h"

namespace aerial::testing {
namespace {

class PublicApi : public GpuTest {};

Tables SmallPublicTables(const Device& device) {
  return Tables::LoadOrPrecompute(device, AtmosphereParameters::Earth(), PrecomputeOptions::Small());
}

// Froxels::Record into a command buffer of the caller's equals, bit for bit, the volume aerial's
// renderer builds with shadows off for the same camera and sun (sunset: the Earth's shadow and a
// long, reddened path through the volume), and it holds light: the far slices scatter and
// attenuate.
TEST_F(PublicApi, FroxelsRecordedByTheCallerEqualTheRenderersUnshadowedVolume) {
  Device device;
  Tables tables = SmallPublicTables(device);
  const vk::Context& context = *ImplOf(device).context;
  const double R = tables.atmosphere().bottom_radius_m;
  Scene scene = BuildPreset("sunset", R);
  RenderOptions options{.width = 160, .height = 90, .shadows = false};
  Renderer renderer(ImplOf(tables).tables(), scene, options);
  renderer.Render(scene);
  FroxelTexels expected = renderer.froxels().Read(context, renderer.frame_uniforms());

  Froxels froxels(device, options.froxels);
  FrameCamera camera = MakeFrameCamera(scene, options.width, options.height);
  context.Submit([&](const vk::CommandBuffer& cmd) { froxels.Record(*cmd, tables, camera); });
  FroxelTexels built = ImplOf(froxels).volume.Read(context, renderer.frame_uniforms());

  const size_t texels = size_t(options.froxels.width) * options.froxels.height * options.froxels.depth;
  ASSERT_EQ(built.rayleigh.size(), 4 * texels);
  EXPECT_TRUE(built.rayleigh == expected.rayleigh);
  EXPECT_TRUE(built.mie == expected.mie);
  EXPECT_TRUE(built.transmittance == expected.transmittance);
  EXPECT_GT(*std::max_element(built.rayleigh.begin(), built.rayleigh.end()), 0.0f);
  EXPECT_LT(*std::min_element(built.transmittance.begin(), built.transmittance.end()), 0.9f);
}

// The precompute tells the caller's callback of every pass, in order, on the caller's thread, and
// draws nothing itself: stderr is a terminal meanwhile, where a progress bar would show.
TEST_F(PublicApi, PrecomputeReportsEachPassToTheCallbackAndDrawsNothing) {
  PseudoTerminal terminal;
  if (!terminal.available()) GTEST_SKIP() << "no pseudo-terminal available";
  Device device;
  struct Step {
    int done, total;
    std::string pass;
    std::thread::id thread;
  };
  std::vector<Step> steps;
  TableLoadOptions load{.read_cache = false,
                        .write_cache = false,
                        .progress = [&](int done, int total, std::string_view pass) {
                          steps.push_back({done, total, std::string(pass), std::this_thread::get_id()});
                        }};
  std::fflush(stderr);
  const int saved_stderr = ::dup(STDERR_FILENO);
  ::dup2(::fileno(terminal.file()), STDERR_FILENO);
  Tables tables = Tables::LoadOrPrecompute(device, AtmosphereParameters::Earth(), PrecomputeOptions::Small(), load);
  std::fflush(stderr);
  ::dup2(saved_stderr, STDERR_FILENO);
  ::close(saved_stderr);
  std::fputs("end", terminal.file());
  EXPECT_EQ(terminal.ReadUntil("end"), "end");

  const std::vector<PassTime>& passes = tables.precompute_times();
  ASSERT_GT(passes.size(), 3u);
  ASSERT_EQ(steps.size(), passes.size());
  for (size_t i = 0; i < steps.size(); ++i) {
    EXPECT_EQ(steps[i].done, int(i) + 1);
    EXPECT_EQ(steps[i].total, int(passes.size()));
    EXPECT_EQ(steps[i].pass, passes[i].pass);
    EXPECT_EQ(steps[i].thread, std::this_thread::get_id());
  }
}

// The images a caller binds are aerial's tables and volume, with their sizes, in the GENERAL
// layout, each with a sampler.
TEST_F(PublicApi, TablesAndFroxelsHandOutBindableImagesAndBlocks) {
  Device device;
  Tables tables = SmallPublicTables(device);
  const PrecomputeOptions small = PrecomputeOptions::Small();
  SampledImage transmittance = tables.transmittance();
  EXPECT_EQ(transmittance.extent.width, uint32_t(small.resolution.transmittance_mu));
  EXPECT_EQ(transmittance.extent.height, uint32_t(small.resolution.transmittance_r));
  SampledImage rayleigh = tables.rayleigh();
  EXPECT_EQ(rayleigh.extent.width, uint32_t(small.resolution.scattering_nu * small.resolution.scattering_mu_s));
  EXPECT_EQ(rayleigh.extent.depth, uint32_t(small.resolution.scattering_r));
  for (const SampledImage& image : {transmittance, tables.irradiance(), rayleigh, tables.mie(), tables.multiple(),
                                    tables.multiple_density()}) {
    EXPECT_NE(image.view, VK_NULL_HANDLE);
    EXPECT_NE(image.sampler, VK_NULL_HANDLE);
    EXPECT_EQ(image.layout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(image.format, VK_FORMAT_R32G32B32A32_SFLOAT);
  }
  Froxels froxels(device, FroxelGrid{.width = 8, .height = 4, .depth = 16});
  EXPECT_EQ(froxels.rayleigh().extent.width, 8u);
  EXPECT_EQ(froxels.mie().extent.height, 4u);
  EXPECT_EQ(froxels.transmittance().extent.depth, 16u);
}

// Tables stored by one device and loaded by another are the same tables; a file made for other
// options is refused, naming the cache key.
TEST_F(PublicApi, TablesStoredAndLoadedAgainAnswerTheSameProbe) {
  Device device;
  Tables tables = SmallPublicTables(device);
  std::filesystem::path file = std::filesystem::path(::testing::TempDir()) / "public_api_tables.bin";
  tables.Store(file);
  Device other;
  Tables loaded = Tables::Load(other, AtmosphereParameters::Earth(), PrecomputeOptions::Small(), file);
  ProbeQuery query{ToRayParameters({.altitude_m = 1000.0, .view_zenith_deg = 80.0, .sun_zenith_deg = 60.0},
                                   AtmosphereParameters::Earth()),
                   5000.0};
  ProbeResult original = Probe(tables, {&query, 1})[0], reread = Probe(loaded, {&query, 1})[0];
  EXPECT_EQ(original.sky_radiance, reread.sky_radiance);
  EXPECT_EQ(original.radiance_to_point, reread.radiance_to_point);
  EXPECT_GT(original.sky_radiance[2], 0.0);
  PrecomputeOptions other_orders = PrecomputeOptions::Small();
  other_orders.orders = 3;
  try {
    Tables::Load(other, AtmosphereParameters::Earth(), other_orders, file);
    ADD_FAILURE() << "tables for 4 orders loaded as tables for 3";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "cache key");
  }
  std::filesystem::remove(file);
}

// A camera the volume cannot be built for is refused before anything is recorded.
TEST_F(PublicApi, FroxelsRefuseAnEmptyViewportAndANonFiniteCamera) {
  Device device;
  Tables tables = SmallPublicTables(device);
  Froxels froxels(device);
  FrameCamera camera = MakeFrameCamera(BuildPreset("noon", tables.atmosphere().bottom_radius_m), 64, 32);
  FrameCamera empty = camera;
  empty.width = 0;
  FrameCamera broken = camera;
  broken.position_m[2] = std::nan("");
  const vk::Context& context = *ImplOf(device).context;
  for (const FrameCamera& bad : {empty, broken}) {
    try {
      context.Submit([&](const vk::CommandBuffer& cmd) { froxels.Record(*cmd, tables, bad); });
      ADD_FAILURE() << "a bad camera was recorded";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("camera"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace aerial::testing
