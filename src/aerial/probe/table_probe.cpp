#include "aerial/probe/table_probe.h"

#include <array>
#include <cstring>

#include "aerial/vk/compute_pipeline.h"

namespace aerial {
namespace {

// std430 mirrors of probe.comp's ProbeQuery and ProbeResult.
struct GpuQuery {
  std::array<float, 4> geometry;
  std::array<float, 4> segment;
};
constexpr int kResultVectors = 9;
struct GpuResult {
  std::array<std::array<float, 4>, kResultVectors> values;
};

Spectrum ToSpectrum(const std::array<float, 4>& v) { return {v[0], v[1], v[2]}; }

}  // namespace

std::vector<ProbeResult> ProbeTables(const AtmosphereTables& tables,
                                     std::span<const ProbeQuery> queries) {
  if (queries.empty()) return {};
  const vk::Context& context = tables.context();
  std::vector<GpuQuery> gpu_queries;
  for (const ProbeQuery& q : queries) {
    gpu_queries.push_back({{float(q.ray.r), float(q.ray.mu), float(q.ray.mu_s), float(q.ray.nu)},
                           {float(q.distance_m), 0, 0, 0}});
  }
  vk::Buffer query_buffer(context, {.size = gpu_queries.size() * sizeof(GpuQuery),
                                    .usage = ::vk::BufferUsageFlagBits::eStorageBuffer,
                                    .host_visible = true});
  query_buffer.Write(std::as_bytes(std::span(gpu_queries)));
  vk::Buffer result_buffer(context, {.size = gpu_queries.size() * sizeof(GpuResult),
                                     .usage = ::vk::BufferUsageFlagBits::eStorageBuffer,
                                     .host_visible = true});
  vk::ComputePipeline pipeline(context, "probe/probe.comp",
                               {{"AtmosphereBlock", vk::kUniform}, {"transmittance_texture", vk::kSampled},
                                {"irradiance_texture", vk::kSampled}, {"rayleigh_texture", vk::kSampled},
                                {"mie_texture", vk::kSampled}, {"multiple_texture", vk::kSampled},
                                {"multiple_density_texture", vk::kSampled}, {"Queries", vk::kStorageBuffer},
                                {"Results", vk::kStorageBuffer}},
                               sizeof(int));
  int count = int(queries.size());
  context.Submit([&](const auto& cmd) {
    pipeline.Dispatch(cmd,
                      {vk::UniformBufferSlot{&tables.uniform_buffer()},
                       tables.Sampled(tables.transmittance()),
                       tables.Sampled(tables.irradiance()),
                       tables.Sampled(tables.rayleigh()),
                       tables.Sampled(tables.mie()),
                       tables.Sampled(tables.multiple()),
                       tables.Sampled(tables.multiple_density()),
                       vk::StorageBufferSlot{&query_buffer}, vk::StorageBufferSlot{&result_buffer}},
                      {uint32_t(count), 1, 1}, {32, 1, 1}, &count);
    vk::FullBarrier(cmd);
  });
  std::vector<GpuResult> gpu_results(queries.size());
  std::memcpy(gpu_results.data(), result_buffer.mapped(), gpu_results.size() * sizeof(GpuResult));
  std::vector<ProbeResult> results;
  for (const GpuResult& g : gpu_results) {
    const auto& v = g.values;
    results.push_back({ToSpectrum(v[0]), ToSpectrum(v[1]), ToSpectrum(v[2]), ToSpectrum(v[3]),
                       ToSpectrum(v[4]), ToSpectrum(v[5]), ToSpectrum(v[6]), ToSpectrum(v[7]),
                       ToSpectrum(v[8])});
  }
  return results;
}

}  // namespace aerial
