#include "aerial/cli/memory_uses.h"

#include <gtest/gtest.h>

#include "aerial/error.h"

namespace aerial::cli {
namespace {

// The estimate of an 8192x8192 render (84 bytes a pixel: 5.3 GiB) is over the default budget and
// within an 8 GiB one: --max-memory-mib 8192 lets it through.
TEST(MemoryUses, MaxMemoryLetsALargeRenderThrough) {
  RendererOptions render{{.width = 8192, .height = 8192}};
  std::vector<MemoryUse> uses = Combined(TableMemoryUses(PrecomputeOptions::Default()), FrameMemoryUses(render));
  const uint64_t heap = uint64_t{24} << 30;
  EXPECT_THROW(MakeMemoryBudget(std::nullopt, heap).Check(uses), Error);
  EXPECT_NO_THROW(MakeMemoryBudget(8192, heap).Check(uses));
}

// The parts follow the allocations: 20 bytes a rendered pixel on the device (rgba32f and depth)
// and 32 bytes each per rendered and output pixel for the copies read back and encoded.
TEST(MemoryUses, RenderScaleShrinksTheTargetsNotTheOutput) {
  RenderOptions full{.width = 1000, .height = 1000}, half = full;
  half.render_scale = 0.5;
  FrameMemory a = EstimateFrameMemory(full), b = EstimateFrameMemory(half);
  EXPECT_EQ(a.targets - b.targets, (1'000'000 - 250'000) * 20u);
  EXPECT_EQ(a.readback - b.readback, (1'000'000 - 250'000) * 32u);
}

// The terrain's selection on the GPU holds, per chunk slot and per selection, 216 bytes: the tree's
// node (80), the walk's queues (8), stamps (4) and sort keys (8), two lists of indirect draws (40),
// the children asked for (64), the tile content (8) and the stamps' feedback copy (4). The frame's,
// which leaves out hidden chunks, also holds its blocks' lowest and highest heights (16 vec2s,
// 128) and the blocks as targets (16 vec4s, 256): 600 bytes; besides, under half a
// megabyte for its horizon and the rest. There is one for the frame and, with shadows, one per
// cascade's casters but the nearest's (GpuShadowCasters::Selects), which culls nothing. The CPU's
// selection has none of these; kAuto counts them, its device being unknown.
TEST(MemoryUses, GpuTerrainSelectionCountsItsBuffers) {
  RendererOptions cpu{{.width = 1000, .height = 1000}};
  cpu.terrain_selector = TerrainSelector::kCpu;
  RendererOptions gpu = cpu, automatic = cpu, gpu_unshadowed = cpu, cpu_unshadowed = cpu;
  gpu.terrain_selector = gpu_unshadowed.terrain_selector = TerrainSelector::kGpu;
  automatic.terrain_selector = TerrainSelector::kAuto;
  gpu_unshadowed.shadows = cpu_unshadowed.shadows = false;
  const uint64_t frame_selection = 8192 * 600, caster_selection = 8192 * 216;
  const uint64_t all = EstimateFrameMemory(gpu).terrain - EstimateFrameMemory(cpu).terrain;
  EXPECT_GE(all, frame_selection + 3 * caster_selection);
  EXPECT_LE(all, frame_selection + 3 * caster_selection + 4 * (512u << 10));
  const uint64_t one = EstimateFrameMemory(gpu_unshadowed).terrain - EstimateFrameMemory(cpu_unshadowed).terrain;
  EXPECT_GE(one, frame_selection);
  EXPECT_LE(one, frame_selection + (512u << 10));
  EXPECT_EQ(EstimateFrameMemory(automatic).terrain, EstimateFrameMemory(gpu).terrain);
}

// A frame whose aerial perspective is applied in a full-screen pass (the per-pixel modes by
// default, the froxels with --froxel-reads full-screen) also holds the surfaces' radiance for it:
// 16 more bytes a rendered pixel (rgba32f).
TEST(MemoryUses, FullScreenPassCountsTheSurfacesRadiance) {
  RendererOptions froxels{{.width = 1000, .height = 1000}};
  RendererOptions marched = froxels, in_fragments = froxels, froxels_deferred = froxels;
  marched.mode = AerialMode::kPerPixel;
  in_fragments.mode = AerialMode::kPerPixel;
  in_fragments.per_pixel_in_full_screen_pass = false;
  froxels_deferred.surface_froxel_reads = SurfaceFroxelReads::kFullScreenPass;
  const uint64_t base = EstimateFrameMemory(froxels).targets;
  EXPECT_EQ(EstimateFrameMemory(marched).targets - base, 1'000'000u * 16);
  EXPECT_EQ(EstimateFrameMemory(in_fragments).targets, base);
  EXPECT_EQ(EstimateFrameMemory(froxels_deferred).targets - base, 1'000'000u * 16);
  // The public estimate, for a caller's renderer, counts it for the per-pixel modes.
  EXPECT_EQ(EstimateFrameMemory(static_cast<const RenderOptions&>(marched)).targets - base, 1'000'000u * 16);
}

// What the tables take is what AtmosphereTables allocates: 2 scattering tables in 4D (Rayleigh in
// the tables' precision, half floats by default, and Mie in float32), 3 in 3D (float32 by
// default), and the multiple density table (in the tables' precision).
TEST(MemoryUses, TableMemoryCountsEveryTable) {
  TableBytes t4 = TableMemory(PrecomputeOptions::Default(LutVariant::k4D));
  EXPECT_EQ(t4.transmittance, 256u * 64 * 16);
  EXPECT_EQ(t4.irradiance, 64u * 32 * 16);
  EXPECT_EQ(t4.scattering, 9u * 36 * 128 * 32 * (8 + 16));
  EXPECT_EQ(t4.multiple_density, 9u * 36 * 64 * 32 * 8);
  PrecomputeOptions float32 = PrecomputeOptions::Default(LutVariant::k4D);
  float32.precision = TablePrecision::kFloat32;
  EXPECT_EQ(TableMemory(float32).scattering, 2u * 9 * 36 * 128 * 32 * 16);
  TableBytes t3 = TableMemory(PrecomputeOptions::Default(LutVariant::k3D));
  EXPECT_EQ(t3.scattering, 3u * 36 * 128 * 32 * 16);
  EXPECT_EQ(t3.multiple_density, 36u * 64 * 32 * 16);
}

// The memory budget (docs/design.md): the default 4D tables take at most 1.25 times the tables at
// Bruneton 2017's scattering resolution (transmittance 256x64, irradiance 64x32, scattering R32
// MU128 MU_S32 NU8). They take 1.11 times: 1.09 with the nine nu slices in half floats
// (docs/accuracy.md, "Nine nu slices in half floats"; 11 would take 1.33), and the multiple density
// table in half floats at the density tables' own texels the rest (docs/accuracy.md, "J_ms on the
// density tables' r texels").
TEST(MemoryUses, DefaultTablesWithinTheLowSunMemoryBudget) {
  const uint64_t before = 256u * 64 * 16 + 64u * 32 * 16 + 2u * 8 * 32 * 128 * 32 * 16;
  uint64_t now = TableMemory(PrecomputeOptions::Default(LutVariant::k4D)).total();
  EXPECT_LE(double(now), 1.25 * double(before));
  EXPECT_GT(double(now), 1.05 * double(before));
}

uint64_t Total(const std::vector<MemoryUse>& uses) {
  uint64_t total = 0;
  for (const MemoryUse& use : uses) total += use.bytes;
  return total;
}

// The spectral precompute keeps the orders >= 2 of every other wavelength for every texel of the
// tables it sums (4 bytes each), beside the group tables and their copies: the estimate grows with
// --wavelengths by at least that. Before, it followed neither --colour nor --wavelengths (24
// wavelengths peaked 127 MiB above an rgb run estimated the same).
TEST(MemoryUses, SpectralEstimateFollowsTheWavelengths) {
  PrecomputeOptions rgb = PrecomputeOptions::Small(), spectral12 = rgb, spectral24 = rgb;
  spectral12.colour = spectral24.colour = ColourMode::kSpectral;
  spectral24.spectral_wavelengths = 24;
  const TableResolution& r = rgb.resolution;
  // The tables the sums hold, in texels: Rayleigh and Mie, the density table, the irradiance.
  const uint64_t texels = 2 * uint64_t(r.scattering_r) * r.scattering_mu * r.scattering_mu_s * r.scattering_nu +
                          uint64_t(r.multiple_density_r) * r.multiple_density_mu * r.multiple_density_mu_s *
                              r.multiple_density_nu +
                          uint64_t(r.irradiance_mu_s) * r.irradiance_r;
  const uint64_t a = Total(TableMemoryUses(rgb)), b = Total(TableMemoryUses(spectral12)),
                 c = Total(TableMemoryUses(spectral24));
  EXPECT_GE(b, a + 6 * texels * 4);
  EXPECT_GE(c, b + 6 * texels * 4) << "12 more wavelengths, 6 more with all orders";
  EXPECT_NE(TableMemoryUses(spectral24)[2].what.find("spectral, 24 wavelengths"), std::string::npos);
}

}  // namespace
}  // namespace aerial::cli
