#pragma once
// The precomputed tables on the GPU, for either variant, behind one interface: transmittance
// T(r, mu), ground irradiance E(r, mu_s), and Rayleigh and Mie scattering without phase, 4D packed
// in 3D (x = nu * MU_S + mu_s) or 3D (nu dropped). Multiple scattering is folded into the Rayleigh
// table as S_n / P_R(nu) in 4D; a 3D table has no nu to divide by, so there it has a table of its
// own ("multiple", 1x1x1 and unused in 4D) that lookups add as S_n / P_R(nu) of the query.
// Besides the radiance tables, the scattering density of orders >= 2 ("multiple_density", J_ms,
// on a coarse grid of the same axes) lets render-time marches integrate a segment's multiple
// scattering directly (Bruneton 2008 eq. 12 restricted to the segment).
// Shaders read them through shaders/include/sky_lookup.glsl whatever the variant.
#include <memory>
#include <string_view>

#include "aerial/atmosphere.h"
#include "aerial/precompute/atmosphere_uniforms.h"
#include "aerial/precompute/table_cache.h"
#include "aerial/table_options.h"
#include "aerial/version.h"
#include "aerial/vk/descriptors.h"
#include "aerial/vk/resources.h"

namespace aerial {

// The cache key of tables computed for these parameters by this build: the atmosphere, the
// options, the shaders and aerial's version (tables computed by another build or release are
// recomputed).
TableCacheKey MakeTableCacheKey(const AtmosphereParameters& atmosphere,
                                const PrecomputeOptions& options,
                                std::string_view version = AERIAL_VERSION);

class AtmosphereTables {
 public:
  // Allocates the tables (contents undefined until Precompute or Load).
  AtmosphereTables(const vk::Context& context, const AtmosphereParameters& atmosphere,
                   const PrecomputeOptions& options);

  const vk::Context& context() const { return context_; }
  const AtmosphereParameters& atmosphere() const { return atmosphere_; }
  const PrecomputeOptions& options() const { return options_; }
  const AtmosphereUniforms& uniforms() const { return uniforms_; }
  const vk::Buffer& uniform_buffer() const { return uniform_buffer_; }
  // An image (a table, or any other) as shaders sample the tables: linear, clamped to the edge.
  vk::SampledImageSlot Sampled(const vk::Image& image) const { return {&image, *sampler_}; }

  const vk::Image& transmittance() const { return transmittance_; }
  const vk::Image& irradiance() const { return irradiance_; }
  const vk::Image& rayleigh() const { return rayleigh_; }
  const vk::Image& mie() const { return mie_; }
  const vk::Image& multiple() const { return multiple_; }
  const vk::Image& multiple_density() const { return multiple_density_; }

  // GPU memory of the tables, in bytes (TableMemory(options()).total()).
  size_t table_bytes() const;
  TableCacheKey cache_key() const;

  // Reads the tables back for the cache, or uploads cached ones.
  TableCache Download() const;
  void Upload(const TableCache& cache);

 private:
  const vk::Context& context_;
  AtmosphereParameters atmosphere_;
  PrecomputeOptions options_;
  AtmosphereUniforms uniforms_;
  vk::Buffer uniform_buffer_;
  ::vk::raii::Sampler sampler_;
  vk::Image transmittance_;
  vk::Image irradiance_;
  vk::Image rayleigh_;
  vk::Image mie_;
  vk::Image multiple_;
  vk::Image multiple_density_;
};

}  // namespace aerial
