// aerial::Tables (include/aerial/tables.h) over the table store and AtmosphereTables.
#include "aerial/api/impl.h"
#include "aerial/precompute/table_cache.h"

namespace aerial {

SampledImage ToSampledImage(const vk::SampledImageSlot& sampled) {
  const vk::Image& image = *sampled.image;
  ::vk::Extent3D extent = image.extent();
  return {.image = image.handle(),
          .view = image.view(),
          .sampler = sampled.sampler,
          .layout = VK_IMAGE_LAYOUT_GENERAL,  // where aerial's images live (vk/resources.h)
          .format = VkFormat(image.format()),
          .extent = {extent.width, extent.height, extent.depth}};
}

SampledImage SampledLikeTheTables(const AtmosphereTables& tables, const vk::Image& image) {
  return ToSampledImage(tables.Sampled(image));
}

namespace {

// One of the tables with the tables' sampler.
SampledImage Public(const AtmosphereTables& tables, const vk::Image& (AtmosphereTables::*table)() const) {
  return SampledLikeTheTables(tables, (tables.*table)());
}

// Tables for these parameters on the device, filled with texels read back before (a file, a
// snapshot); Upload checks each table's name and size.
LoadedTables Uploaded(const Device& device, const AtmosphereParameters& atmosphere,
                      const PrecomputeOptions& options, const TableCache& texels) {
  LoadedTables loaded{.tables = std::make_unique<AtmosphereTables>(*ImplOf(device).context, atmosphere, options)};
  loaded.tables->Upload(texels);
  return loaded;
}

}  // namespace

Tables::Tables(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Tables::~Tables() = default;
Tables::Tables(Tables&&) noexcept = default;
Tables& Tables::operator=(Tables&&) noexcept = default;

Tables Tables::LoadOrPrecompute(const Device& device, const AtmosphereParameters& atmosphere,
                                const PrecomputeOptions& options, const TableLoadOptions& load) {
  Validate(atmosphere);
  TableStoreOptions store{.cache_dir = load.cache_dir,
                          .read_cache = load.read_cache,
                          .write_cache = load.write_cache,
                          .require_cache_write = load.require_cache_write,
                          .progress = load.progress};
  return Tables(std::make_unique<Impl>(
      Impl{aerial::LoadOrPrecompute(*ImplOf(device).context, atmosphere, options, store)}));
}

Tables Tables::Load(const Device& device, const AtmosphereParameters& atmosphere,
                    const PrecomputeOptions& options, const std::filesystem::path& file) {
  Validate(atmosphere);
  options.Validate();
  LoadedTables loaded =
      Uploaded(device, atmosphere, options, ReadTableCache(file, MakeTableCacheKey(atmosphere, options)));
  loaded.from_cache = true;
  loaded.cache_file = file;
  return Tables(std::make_unique<Impl>(Impl{std::move(loaded)}));
}

void Tables::Store(const std::filesystem::path& file) const { WriteTableCache(file, impl_->tables().Download()); }

TableSnapshot Tables::Snapshot() const {
  return TableSnapshot(std::make_unique<TableSnapshot::Impl>(
      TableSnapshot::Impl{atmosphere(), options(), impl_->tables().Download()}));
}

Tables Tables::FromSnapshot(const Device& device, const TableSnapshot& snapshot) {
  const TableSnapshot::Impl& taken = ImplOf(snapshot);
  return Tables(std::make_unique<Impl>(Impl{Uploaded(device, taken.atmosphere, taken.options, taken.texels)}));
}

TableSnapshot::TableSnapshot(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TableSnapshot::~TableSnapshot() = default;
TableSnapshot::TableSnapshot(TableSnapshot&&) noexcept = default;
TableSnapshot& TableSnapshot::operator=(TableSnapshot&&) noexcept = default;
const AtmosphereParameters& TableSnapshot::atmosphere() const { return impl_->atmosphere; }
const PrecomputeOptions& TableSnapshot::options() const { return impl_->options; }

const AtmosphereParameters& Tables::atmosphere() const { return impl_->tables().atmosphere(); }
const PrecomputeOptions& Tables::options() const { return impl_->tables().options(); }
bool Tables::from_cache() const { return impl_->loaded.from_cache; }
std::filesystem::path Tables::cache_file() const { return impl_->loaded.cache_file; }
uint64_t Tables::gpu_bytes() const { return impl_->tables().table_bytes(); }
const std::vector<PassTime>& Tables::precompute_times() const { return impl_->loaded.pass_times; }

UniformBlock Tables::atmosphere_block() const {
  const vk::Buffer& buffer = impl_->tables().uniform_buffer();
  return {buffer.handle(), buffer.size()};
}

SampledImage Tables::transmittance() const { return Public(impl_->tables(), &AtmosphereTables::transmittance); }
SampledImage Tables::irradiance() const { return Public(impl_->tables(), &AtmosphereTables::irradiance); }
SampledImage Tables::rayleigh() const { return Public(impl_->tables(), &AtmosphereTables::rayleigh); }
SampledImage Tables::mie() const { return Public(impl_->tables(), &AtmosphereTables::mie); }
SampledImage Tables::multiple() const { return Public(impl_->tables(), &AtmosphereTables::multiple); }
SampledImage Tables::multiple_density() const {
  return Public(impl_->tables(), &AtmosphereTables::multiple_density);
}

}  // namespace aerial
