#include "aerial/precompute/atmosphere_tables.h"

#include <array>
#include <cstring>

#include "aerial/core/checksum.h"
#include "aerial/error.h"
#include "aerial/vk/shader_registry.h"

namespace aerial {
namespace {

::vk::Format ScatteringFormat(TablePrecision precision) {
  return precision == TablePrecision::kFloat32 ? ::vk::Format::eR32G32B32A32Sfloat
                                               : ::vk::Format::eR16G16B16A16Sfloat;
}

::vk::Extent3D ScatteringExtent(const TableResolution& r) {
  return {uint32_t(r.scattering_nu * r.scattering_mu_s), uint32_t(r.scattering_mu),
          uint32_t(r.scattering_r)};
}

TexelFormat ToTexelFormat(::vk::Format format) {
  return format == ::vk::Format::eR16G16B16A16Sfloat ? TexelFormat::kRgba16f : TexelFormat::kRgba32f;
}

::vk::Extent3D MultipleDensityExtent(const TableResolution& r) {
  return {uint32_t(r.multiple_density_nu * r.multiple_density_mu_s), uint32_t(r.multiple_density_mu),
          uint32_t(r.multiple_density_r)};
}

uint64_t Texels(const ::vk::Extent3D& e) { return uint64_t(e.width) * e.height * e.depth; }

}  // namespace

TableBytes TableMemory(const PrecomputeOptions& options) {
  const TableResolution& r = options.resolution;
  // Rayleigh and J_ms in the tables' precision, Mie in float32; the 3D variant adds its multiple
  // scattering table (1 texel in 4D, not counted).
  int tables_in_precision = options.variant == LutVariant::k3D ? 2 : 1;
  return {.transmittance = uint64_t(r.transmittance_mu) * r.transmittance_r * 16,
          .irradiance = uint64_t(r.irradiance_mu_s) * r.irradiance_r * 16,
          .scattering = Texels(ScatteringExtent(r)) *
                        (tables_in_precision * TexelBytes(ToTexelFormat(ScatteringFormat(options.precision))) +
                         TexelBytes(TexelFormat::kRgba32f)),
          .multiple_density =
              Texels(MultipleDensityExtent(r)) * TexelBytes(ToTexelFormat(ScatteringFormat(options.precision)))};
}

AtmosphereTables::AtmosphereTables(const vk::Context& context,
                                   const AtmosphereParameters& atmosphere,
                                   const PrecomputeOptions& options)
    : context_(context),
      atmosphere_(atmosphere),
      options_(options),
      uniforms_(MakeAtmosphereUniforms(atmosphere, options)),
      uniform_buffer_(context, vk::UniformBufferInfo(sizeof(AtmosphereUniforms))),
      sampler_(vk::CreateLinearClampSampler(context)),
      // Transmittance and irradiance stay float32 in every precision: they are tiny, and half
      // floats band visibly in the transmittance (Bruneton 2017 notes the same).
      transmittance_(context, {.extent = {uint32_t(options.resolution.transmittance_mu),
                                          uint32_t(options.resolution.transmittance_r), 1}}),
      irradiance_(context, {.extent = {uint32_t(options.resolution.irradiance_mu_s),
                                       uint32_t(options.resolution.irradiance_r), 1}}),
      rayleigh_(context, {.extent = ScatteringExtent(options.resolution),
                          .format = ScatteringFormat(options.precision)}),
      // Mie's single scattering stays float32: above a few km it falls below half floats' normal
      // range (6.1e-5), where their steps are 6e-8 apart. In half floats, looking up from 10 km at
      // a sun in the zenith, it read 3.8% off in red (TablesVsReference).
      mie_(context, {.extent = ScatteringExtent(options.resolution)}),
      multiple_(context, {.extent = options.variant == LutVariant::k3D
                                        ? ScatteringExtent(options.resolution)
                                        : ::vk::Extent3D{1, 1, 1},
                          .volume = true,
                          .format = ScatteringFormat(options.precision)}),
      // J_ms (radiance per metre, 1e-9 at twilight to 1e-6) is stored times
      // kMultipleDensityScale, which puts it in half floats' normal range.
      multiple_density_(context, {.extent = MultipleDensityExtent(options.resolution),
                                  .volume = true,
                                  .format = ScatteringFormat(options.precision)}) {
  uniform_buffer_.Write(std::as_bytes(std::span(&uniforms_, 1)));
  context_.Submit([&](const auto& cmd) {
    for (const vk::Image* image :
         {&transmittance_, &irradiance_, &rayleigh_, &mie_, &multiple_, &multiple_density_}) {
      image->InitializeLayout(cmd);
    }
    multiple_.Clear(cmd);  // stays zero in 4D
  });
}

size_t AtmosphereTables::table_bytes() const { return TableMemory(options_).total(); }

TableCacheKey MakeTableCacheKey(const AtmosphereParameters& atmosphere,
                                const PrecomputeOptions& options, std::string_view version) {
  return {.atmosphere_hash = atmosphere.Hash(),
          .options_hash = options.Hash() ^ shaders::Fingerprint() ^ Checksum(version)};
}

TableCacheKey AtmosphereTables::cache_key() const { return MakeTableCacheKey(atmosphere_, options_); }

namespace {

struct NamedImage {
  const char* name;
  const vk::Image* image;
};

// The tables under their names in the cache file.
std::array<NamedImage, 6> NamedTables(const AtmosphereTables& t) {
  return {NamedImage{"transmittance", &t.transmittance()}, NamedImage{"irradiance", &t.irradiance()},
          NamedImage{"rayleigh", &t.rayleigh()},           NamedImage{"mie", &t.mie()},
          NamedImage{"multiple", &t.multiple()},           NamedImage{"multiple_density", &t.multiple_density()}};
}

}  // namespace

TableCache AtmosphereTables::Download() const {
  TableCache cache;
  cache.key = cache_key();
  cache.description = atmosphere_.name + ": " + options_.Describe();
  for (NamedImage table : NamedTables(*this)) {
    ::vk::Extent3D e = table.image->extent();
    CachedTable cached{.name = table.name, .width = e.width, .height = e.height, .depth = e.depth,
                       .format = ToTexelFormat(table.image->format()),
                       .texels = vk::ReadImageBytes(context_, *table.image)};
    cache.tables.push_back(std::move(cached));
  }
  return cache;
}

void AtmosphereTables::Upload(const TableCache& cache) {
  for (NamedImage table : NamedTables(*this)) {
    const CachedTable* cached = nullptr;
    for (const auto& t : cache.tables)
      if (t.name == table.name) cached = &t;
    ::vk::Extent3D e = table.image->extent();
    if (!cached || cached->width != e.width || cached->height != e.height ||
        cached->depth != e.depth || cached->texels.size() != table.image->byte_size())
      throw Error(std::string("cache table ") + table.name, cached ? "wrong size" : "missing",
                  std::to_string(e.width) + "x" + std::to_string(e.height) + "x" + std::to_string(e.depth));
    vk::Buffer staging(context_, {.size = cached->texels.size(),
                                  .usage = ::vk::BufferUsageFlagBits::eTransferSrc,
                                  .host_visible = true});
    staging.Write(cached->texels);
    context_.Submit([&](const auto& cmd) {
      table.image->CopyFromBuffer(cmd, staging);
      vk::FullBarrier(cmd);
    });
  }
}

}  // namespace aerial
