#include "aerial/precompute/precomputer.h"

#include <array>
#include <optional>

#include "aerial/core/progress.h"
#include "aerial/precompute/sample_counts.h"
#include "aerial/precompute/spectral_precompute.h"
#include "aerial/vk/compute_pipeline.h"

namespace aerial {
namespace {

using vk::kSampled;
using vk::kStorageBuffer;
using vk::kStorageImage;
using vk::kUniform;

// Push constants of the passes that add an order to a final table: the order, and whether it is
// the last one and the orders beyond are to be added as a geometric series.
struct SeriesStep {
  int order;
  int close_series;
};

// Push constants of accumulate_multiple_scattering.comp.
struct AccumulateStep {
  std::array<int, 4> target_size;  // r, mu, mu_s, nu
  int close_series;
  int divide_by_rayleigh_phase;
  int mu_axis;  // of the source and the target (mappings.glsl)
  float scale;  // of what is added: J_ms's kMultipleDensityScale, 1 for the radiance
};
// mappings.glsl's MU_AXIS_*: radiance tables map mu by the ray's length, densities by the angle.
constexpr int kMuAxisRayLength = 0;
constexpr int kMuAxisViewZenith = 1;

vk::SlotLayout TransmittanceSlots() {
  return {{"AtmosphereBlock", kUniform}, {"transmittance_image", kStorageImage}};
}

vk::SlotLayout MultipleScatteringSlots() {
  return {{"AtmosphereBlock", kUniform}, {"transmittance_texture", kSampled},
          {"scattering_density_texture", kSampled},
          {"delta_multiple_scattering_image", kStorageImage}};
}

// The passes' pipelines; slots in binding order, named as in each shader (checked). Order 2's
// multiple scattering pass reads its density blended exponentially in mu_s in the Earth's shadow
// (specialization constant 1, multiple_scattering.comp).
struct Pipelines {
  explicit Pipelines(const vk::Context& c)
      : transmittance(c, "precompute/transmittance.comp", TransmittanceSlots()),
        sun_band(c, "precompute/sun_band.comp",
                 {{"AtmosphereBlock", kUniform}, {"transmittance_texture", kSampled},
                  {"sun_band_image", kStorageImage}}),
        direct_irradiance(c, "precompute/direct_irradiance.comp",
                          {{"AtmosphereBlock", kUniform}, {"transmittance_texture", kSampled},
                           {"delta_irradiance_image", kStorageImage}}),
        single_scattering(c, "precompute/single_scattering.comp",
                          {{"AtmosphereBlock", kUniform}, {"transmittance_texture", kSampled},
                           {"delta_rayleigh_image", kStorageImage}, {"single_mie_image", kStorageImage},
                           {"rayleigh_accumulator", kStorageImage}, {"sun_band_texture", kSampled}}),
        incident_radiance(c, "precompute/incident_radiance.comp",
                          {{"AtmosphereBlock", kUniform}, {"transmittance_texture", kSampled},
                           {"single_rayleigh_texture", kSampled}, {"single_mie_texture", kSampled},
                           {"multiple_scattering_texture", kSampled}, {"delta_irradiance_texture", kSampled},
                           {"IncidentRadiance", kStorageBuffer}, {"Directions", kStorageBuffer}},
                          sizeof(int)),
        scattering_density(c, "precompute/scattering_density.comp",
                           {{"AtmosphereBlock", kUniform}, {"IncidentRadiance", kStorageBuffer},
                            {"Directions", kStorageBuffer}, {"scattering_density_image", kStorageImage}}),
        indirect_irradiance(c, "precompute/indirect_irradiance.comp",
                            {{"AtmosphereBlock", kUniform}, {"single_rayleigh_texture", kSampled},
                             {"single_mie_texture", kSampled}, {"multiple_scattering_texture", kSampled},
                             {"previous_delta_irradiance", kSampled}, {"delta_irradiance_image", kStorageImage},
                             {"irradiance_accumulator", kStorageImage}, {"transmittance_texture", kSampled},
                             {"sun_band_texture", kSampled}},
                            sizeof(SeriesStep)),
        multiple_scattering(c, "precompute/multiple_scattering.comp", MultipleScatteringSlots(), 0,
                            {0}),
        multiple_scattering_order2(c, "precompute/multiple_scattering.comp",
                                   MultipleScatteringSlots(), 0, {1}),
        accumulate(c, "precompute/accumulate_multiple_scattering.comp",
                   {{"AtmosphereBlock", kUniform}, {"order_texture", kSampled},
                    {"previous_order_texture", kSampled}, {"accumulator", kStorageImage}},
                   sizeof(AccumulateStep)),
        round_to_half(c, "precompute/round_to_half.comp", {{"table", kStorageImage}}) {}
  vk::ComputePipeline transmittance, sun_band, direct_irradiance, single_scattering, incident_radiance,
      scattering_density, indirect_irradiance, multiple_scattering, multiple_scattering_order2,
      accumulate, round_to_half;
};

// The sizes of the intermediate tables, from the options alone (so that their memory can be
// estimated before anything is allocated).
::vk::Extent3D DensityExtent(const PrecomputeOptions& o) {
  const SampleCounts s = SampleCountsOf(o);
  return {uint32_t(s.density_nu * s.density_mu_s), uint32_t(s.density_mu), uint32_t(s.density_r)};
}
size_t DirectionCount(const PrecomputeOptions& o) {
  const SampleCounts s = SampleCountsOf(o);
  return size_t(s.density_theta_up + s.density_theta_down) * s.density_phi;
}
size_t IncidentBytes(const PrecomputeOptions& o) {
  const SampleCounts s = SampleCountsOf(o);
  return DirectionCount(o) * s.density_r * s.density_mu_s * 16;
}
size_t DirectionBytes(const PrecomputeOptions& o) { return DirectionCount(o) * SampleCountsOf(o).density_r * 16; }

// Intermediate tables that only live during the precomputation. The per-order ground irradiance
// and multiple scattering are kept for two consecutive orders (index: order % 2), so that the last
// order can be compared with the one before it.
struct Scratch {
  Scratch(const vk::Context& c, const AtmosphereTables& tables)
      : sun_band(c, {.extent = SunBandExtent(tables.options())}),
        delta_irradiance{vk::Image(c, {.extent = tables.irradiance().extent()}),
                         vk::Image(c, {.extent = tables.irradiance().extent()})},
        delta_rayleigh(c, {.extent = tables.rayleigh().extent()}),
        delta_multiple{vk::Image(c, {.extent = DensityExtent(tables.options())}),
                       vk::Image(c, {.extent = DensityExtent(tables.options())})},
        density{vk::Image(c, {.extent = DensityExtent(tables.options())}),
                vk::Image(c, {.extent = DensityExtent(tables.options())})},
        incident_radiance(c, {.size = IncidentBytes(tables.options()),
                              .usage = ::vk::BufferUsageFlagBits::eStorageBuffer}),
        directions(c, {.size = DirectionBytes(tables.options()),
                       .usage = ::vk::BufferUsageFlagBits::eStorageBuffer}) {
    // Half-precision tables are accumulated in float32 and converted once at the end.
    if (tables.rayleigh().format() != ::vk::Format::eR32G32B32A32Sfloat) {
      rayleigh_f32.emplace(c, vk::ImageCreateInfo{.extent = tables.rayleigh().extent()});
      multiple_f32.emplace(c, vk::ImageCreateInfo{.extent = tables.multiple().extent(), .volume = true});
      multiple_density_f32.emplace(c, vk::ImageCreateInfo{.extent = tables.multiple_density().extent(), .volume = true});
    }
  }

  vk::Image sun_band;
  std::array<vk::Image, 2> delta_irradiance;
  vk::Image delta_rayleigh;
  std::array<vk::Image, 2> delta_multiple;
  std::array<vk::Image, 2> density;  // J_n, for two consecutive orders (index: order % 2)
  vk::Buffer incident_radiance, directions;
  std::optional<vk::Image> rayleigh_f32, multiple_f32, multiple_density_f32;
};

::vk::Extent3D Extent2D(const vk::Image& image) { return image.extent(); }

void BlitConvert(const vk::CommandBuffer& cmd, const vk::Image& from, const vk::Image& to) {
  ::vk::Extent3D e = from.extent();
  ::vk::ImageSubresourceLayers layers{.aspectMask = ::vk::ImageAspectFlagBits::eColor, .layerCount = 1};
  ::vk::ImageBlit region{
      .srcSubresource = layers,
      .srcOffsets = std::array<::vk::Offset3D, 2>{::vk::Offset3D{0, 0, 0},
                                                   ::vk::Offset3D{int(e.width), int(e.height), int(e.depth)}},
      .dstSubresource = layers,
      .dstOffsets = std::array<::vk::Offset3D, 2>{::vk::Offset3D{0, 0, 0},
                                                   ::vk::Offset3D{int(e.width), int(e.height), int(e.depth)}}};
  cmd.blitImage(from.handle(), ::vk::ImageLayout::eGeneral, to.handle(), ::vk::ImageLayout::eGeneral,
                region, ::vk::Filter::eNearest);
}

}  // namespace

TableBytes PrecomputeScratchMemory(const PrecomputeOptions& options) {
  if (options.colour == ColourMode::kSpectral) {
    // The three-wavelength precomputes and their sums, on top of what an rgb precompute of these
    // tables uses (an overestimate by the rgb scratch that the spectral path does not allocate).
    PrecomputeOptions rgb = options;
    rgb.colour = ColourMode::kRgb;
    TableBytes scratch = PrecomputeScratchMemory(rgb), spectral = SpectralPrecomputeScratchMemory(options);
    return {.transmittance = scratch.transmittance + spectral.transmittance,
            .irradiance = scratch.irradiance + spectral.irradiance,
            .scattering = scratch.scattering + spectral.scattering,
            .multiple_density = scratch.multiple_density + spectral.multiple_density};
  }
  const TableResolution& r = options.resolution;
  const ::vk::Extent3D density = DensityExtent(options);
  uint64_t scattering_texels = uint64_t(r.scattering_nu) * r.scattering_mu_s * r.scattering_mu * r.scattering_r;
  uint64_t scattering = scattering_texels * 16 +                                          // delta_rayleigh
                        4 * uint64_t(density.width) * density.height * density.depth * 16 +  // delta_multiple, density
                        IncidentBytes(options) + DirectionBytes(options);
  // Float32 copies of the half-precision tables: Rayleigh, the 3D variant's multiple one, J_ms.
  uint64_t multiple_density = 0;
  if (options.precision == TablePrecision::kFloat16) {
    scattering += scattering_texels * 16 * (options.variant == LutVariant::k3D ? 2 : 1);
    PrecomputeOptions float32 = options;
    float32.precision = TablePrecision::kFloat32;
    multiple_density = TableMemory(float32).multiple_density;
  }
  const ::vk::Extent3D sun_band = SunBandExtent(options);
  return {.transmittance = uint64_t(sun_band.width) * sun_band.height * 16,
          .irradiance = 2 * uint64_t(r.irradiance_mu_s) * r.irradiance_r * 16,
          .scattering = scattering, .multiple_density = multiple_density};
}

::vk::Extent3D SunBandExtent(const PrecomputeOptions& options) {
  return {256, uint32_t(options.resolution.transmittance_r), 1};
}

int PrecomputePassCount(const PrecomputeOptions& options) {
  if (options.colour == ColourMode::kSpectral) {
    const int all_order_groups = SpectralAllOrderGroupCount(options);
    return (SpectralGroupCount(options) - all_order_groups) * PrecomputePassCount(SpectralGroupOptions(options, false)) +
           all_order_groups * PrecomputePassCount(SpectralGroupOptions(options, true)) + 1;
  }
  // transmittance, sun band, direct irradiance, single scattering, 6 passes per order >= 2, the
  // ground irradiance of the last order, and for half floats the conversion.
  return 4 + 6 * (options.orders - 1) + 1 + (options.precision == TablePrecision::kFloat16 ? 1 : 0);
}

std::vector<vk::PassTime> Precompute(AtmosphereTables& tables, Progress* progress) {
  std::vector<vk::PassTime> times = tables.options().colour == ColourMode::kSpectral
                                        ? PrecomputeSpectral(tables, progress)
                                        : PrecomputeRadiance(tables, progress);
  if (progress) progress->Finish();
  return times;
}

vk::PassTime ComputeTransmittance(AtmosphereTables& tables) {
  const vk::Context& context = tables.context();
  vk::ComputePipeline pipeline(context, "precompute/transmittance.comp", TransmittanceSlots());
  vk::GpuTimer timer(context);
  context.Submit([&](const vk::CommandBuffer& cmd) {
    timer.Reset(cmd);
    timer.Begin(cmd, "transmittance");
    pipeline.Dispatch(cmd, {vk::UniformBufferSlot{&tables.uniform_buffer()}, vk::StorageImageSlot{&tables.transmittance()}},
                      Extent2D(tables.transmittance()), {8, 8, 1});
    timer.End(cmd);
    vk::FullBarrier(cmd);
  });
  return timer.Collect().front();
}

std::vector<vk::PassTime> PrecomputeRadiance(AtmosphereTables& tables, Progress* progress,
                                             const std::function<void()>& after_single_scattering) {
  const vk::Context& context = tables.context();
  Pipelines pipelines(context);
  Scratch scratch(context, tables);
  vk::GpuTimer timer(context);
  std::vector<vk::PassTime> times;
  const vk::Image& rayleigh = scratch.rayleigh_f32 ? *scratch.rayleigh_f32 : tables.rayleigh();
  const vk::Image& mie = tables.mie();  // float32 in every precision
  const vk::Image& multiple = scratch.multiple_f32 ? *scratch.multiple_f32 : tables.multiple();
  const vk::Image& multiple_density =
      scratch.multiple_density_f32 ? *scratch.multiple_density_f32 : tables.multiple_density();
  // 4D folds each order into the Rayleigh table; 3D keeps them in their own table.
  const vk::Image& multiple_accumulator =
      tables.options().variant == LutVariant::k4D ? rayleigh : multiple;
  const vk::Buffer& uniforms = tables.uniform_buffer();
  const SampleCounts samples = SampleCountsOf(tables.options());
  ::vk::Extent3D scattering_threads = tables.rayleigh().extent();
  ::vk::Extent3D density_threads = DensityExtent(tables.options());

  // Each pass is its own submission so that the progress bar advances as the GPU finishes it.
  auto run = [&](const std::string& label, auto&& record) {
    context.Submit([&](const vk::CommandBuffer& cmd) {
      timer.Reset(cmd);
      timer.Begin(cmd, label);
      record(cmd);
      timer.End(cmd);
      vk::FullBarrier(cmd);
    });
    for (auto& t : timer.Collect()) times.push_back(t);
    if (progress) progress->Advance(label);
  };

  context.Submit([&](const auto& cmd) {
    for (const vk::Image* image : {&scratch.sun_band, &scratch.delta_irradiance[0],
                                   &scratch.delta_irradiance[1], &scratch.delta_rayleigh,
                                   &scratch.delta_multiple[0], &scratch.delta_multiple[1],
                                   &scratch.density[0], &scratch.density[1]})
      image->InitializeLayout(cmd);
    if (scratch.rayleigh_f32) {
      scratch.rayleigh_f32->InitializeLayout(cmd);
      scratch.multiple_f32->InitializeLayout(cmd);
      scratch.multiple_f32->Clear(cmd);
      scratch.multiple_density_f32->InitializeLayout(cmd);
    }
    multiple_density.Clear(cmd);  // accumulates orders >= 2
    // The irradiance table accumulates indirect orders only; it starts at zero.
    tables.irradiance().Clear(cmd);
    vk::FullBarrier(cmd);
  });

  // Step 1: transmittance T(r, mu).
  run("transmittance", [&](const auto& cmd) {
    pipelines.transmittance.Dispatch(cmd, {vk::UniformBufferSlot{&uniforms},
                                           vk::StorageImageSlot{&tables.transmittance()}},
                                     Extent2D(tables.transmittance()), {8, 8, 1});
  });
  // Step 1b: the sunlight's transmittance near each radius's horizon, over the sun's disc.
  run("sun band", [&](const auto& cmd) {
    pipelines.sun_band.Dispatch(cmd,
                                {vk::UniformBufferSlot{&uniforms}, tables.Sampled(tables.transmittance()),
                                 vk::StorageImageSlot{&scratch.sun_band}},
                                Extent2D(scratch.sun_band), {8, 8, 1});
  });
  // Step 2: direct irradiance, the ground's order-0 light (delta E_0).
  run("direct irradiance", [&](const auto& cmd) {
    pipelines.direct_irradiance.Dispatch(
        cmd, {vk::UniformBufferSlot{&uniforms}, tables.Sampled(tables.transmittance()),
              vk::StorageImageSlot{&scratch.delta_irradiance[0]}},
        Extent2D(scratch.delta_irradiance[0]), {8, 8, 1});
  });
  // Step 3: single scattering, Rayleigh (delta S_R, and the accumulated table) and Mie.
  run("single scattering", [&](const auto& cmd) {
    pipelines.single_scattering.Dispatch(
        cmd, {vk::UniformBufferSlot{&uniforms}, tables.Sampled(tables.transmittance()),
              vk::StorageImageSlot{&scratch.delta_rayleigh}, vk::StorageImageSlot{&mie},
              vk::StorageImageSlot{&rayleigh}, tables.Sampled(scratch.sun_band)},
        scattering_threads, {8, 8, 1});
  });
  // The ground irradiance of radiance order n: delta E_n, added to the irradiance table (with the
  // orders beyond it when closing the series). delta E_0 is the direct irradiance.
  const int orders = tables.options().orders;
  const bool close_series = tables.options().ClosesSeries();
  auto add_ground_irradiance = [&](int radiance_order) {
    SeriesStep step{radiance_order, close_series && radiance_order == orders};
    run("indirect irradiance (order " + std::to_string(radiance_order) + ")", [&](const auto& cmd) {
      pipelines.indirect_irradiance.Dispatch(
          cmd, {vk::UniformBufferSlot{&uniforms}, tables.Sampled(scratch.delta_rayleigh), tables.Sampled(mie),
                tables.Sampled(scratch.delta_multiple[radiance_order % 2]),
                tables.Sampled(scratch.delta_irradiance[(radiance_order + 1) % 2]),
                vk::StorageImageSlot{&scratch.delta_irradiance[radiance_order % 2]},
                vk::StorageImageSlot{&tables.irradiance()}, tables.Sampled(tables.transmittance()),
                tables.Sampled(scratch.sun_band)},
          Extent2D(tables.irradiance()), {8, 8, 1}, &step);
    });
  };
  // Step 4: for each order n >= 2, the scattering density J_n (from the order n-1 radiance and
  // the ground irradiance of order n-2), the ground irradiance of order n-1, and the order n
  // scattering S_n (at the density resolution), then added to the final table; J_n is added to
  // the multiple density table J_ms.
  for (int order = 2; order <= orders; ++order) {
    std::string suffix = " (order " + std::to_string(order) + ")";
    run("incident radiance" + suffix, [&](const auto& cmd) {
      pipelines.incident_radiance.Dispatch(
          cmd, {vk::UniformBufferSlot{&uniforms}, tables.Sampled(tables.transmittance()),
                tables.Sampled(scratch.delta_rayleigh), tables.Sampled(mie), tables.Sampled(scratch.delta_multiple[(order - 1) % 2]),
                tables.Sampled(scratch.delta_irradiance[order % 2]), vk::StorageBufferSlot{&scratch.incident_radiance},
                vk::StorageBufferSlot{&scratch.directions}},
          {uint32_t(DirectionCount(tables.options())), uint32_t(samples.density_mu_s),
           uint32_t(samples.density_r)},
          {64, 1, 1}, &order);
    });
    run("scattering density" + suffix, [&](const auto& cmd) {
      pipelines.scattering_density.Dispatch(
          cmd, {vk::UniformBufferSlot{&uniforms}, vk::StorageBufferSlot{&scratch.incident_radiance},
                vk::StorageBufferSlot{&scratch.directions}, vk::StorageImageSlot{&scratch.density[order % 2]}},
          {density_threads.height, density_threads.width, density_threads.depth}, {64, 1, 1});
    });
    add_ground_irradiance(order - 1);
    // Nothing of order 2 has reached the tables yet: the accumulations come below.
    if (order == 2 && after_single_scattering) after_single_scattering();
    // The 3D tables have no Earth's shadow (GetDensityBlended is linear there), and lavapipe
    // would pay for the exponential branch all the same (it runs both sides of a branch).
    const vk::ComputePipeline& multiple_scattering =
        order == 2 && tables.options().variant == LutVariant::k4D ? pipelines.multiple_scattering_order2
                                                                  : pipelines.multiple_scattering;
    run("multiple scattering" + suffix, [&](const auto& cmd) {
      multiple_scattering.Dispatch(
          cmd, {vk::UniformBufferSlot{&uniforms}, tables.Sampled(tables.transmittance()),
                tables.Sampled(scratch.density[order % 2]), vk::StorageImageSlot{&scratch.delta_multiple[order % 2]}},
          density_threads, {8, 8, 1});
    });
    int last = close_series && order == orders;
    const TableResolution& res = tables.options().resolution;
    AccumulateStep radiance_step{
        .target_size = {res.scattering_r, res.scattering_mu, res.scattering_mu_s, res.scattering_nu},
        .close_series = last,
        .divide_by_rayleigh_phase = tables.options().variant == LutVariant::k4D,
        .mu_axis = kMuAxisRayLength,
        .scale = 1.0f};
    run("accumulate" + suffix, [&](const auto& cmd) {
      pipelines.accumulate.Dispatch(cmd, {vk::UniformBufferSlot{&uniforms}, tables.Sampled(scratch.delta_multiple[order % 2]),
                                          tables.Sampled(scratch.delta_multiple[(order - 1) % 2]),
                                          vk::StorageImageSlot{&multiple_accumulator}},
                                    scattering_threads, {8, 8, 1}, &radiance_step);
    });
    AccumulateStep density_step{
        .target_size = {res.multiple_density_r, res.multiple_density_mu, res.multiple_density_mu_s,
                        res.multiple_density_nu},
        .close_series = last,
        .divide_by_rayleigh_phase = 0,
        .mu_axis = kMuAxisViewZenith,
        .scale = tables.uniforms().multiple_density_scale};
    run("accumulate density" + suffix, [&](const auto& cmd) {
      pipelines.accumulate.Dispatch(cmd, {vk::UniformBufferSlot{&uniforms}, tables.Sampled(scratch.density[order % 2]),
                                          tables.Sampled(scratch.density[(order - 1) % 2]),
                                          vk::StorageImageSlot{&multiple_density}},
                                    multiple_density.extent(), {8, 8, 1}, &density_step);
    });
  }
  // Step 5: the ground irradiance of the last order, so that the irradiance table holds the same
  // orders as the radiance (Bruneton 2008's Algorithm 4.1 stops at N-1).
  add_ground_irradiance(orders);
  // Step 6, for half floats: each float32 texel rounded to the nearest half, then converted.
  if (scratch.rayleigh_f32) {
    run("half floats", [&](const auto& cmd) {
      for (const vk::Image* table : {&*scratch.rayleigh_f32, &*scratch.multiple_f32, &*scratch.multiple_density_f32})
        pipelines.round_to_half.Dispatch(cmd, {vk::StorageImageSlot{table}}, table->extent(), {8, 8, 1});
      vk::FullBarrier(cmd);
      BlitConvert(cmd, *scratch.rayleigh_f32, tables.rayleigh());
      BlitConvert(cmd, *scratch.multiple_f32, tables.multiple());
      BlitConvert(cmd, *scratch.multiple_density_f32, tables.multiple_density());
    });
  }
  return times;
}

}  // namespace aerial
