#pragma once
// The precomputed atmosphere tables (Bruneton & Neyret 2008; the 3D variant drops nu), on the
// device, as images a caller binds in its own shaders (shaders/include, installed as
// share/aerial/glsl, reads them: aerial_perspective.glsl).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include <vulkan/vulkan_core.h>

#include "aerial/atmosphere.h"
#include "aerial/device.h"
#include "aerial/table_options.h"

namespace aerial {

// An image as shaders sample it: the view, aerial's sampler for it (linear, clamped to the edge),
// the layout it stays in, its format and size.
struct SampledImage {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  VkImageLayout layout = VK_IMAGE_LAYOUT_GENERAL;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent3D extent{};
};

// A uniform block aerial fills, for the caller's descriptor sets.
struct UniformBlock {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
};

// Called on the calling thread after each precompute pass: done of total passes (1..total, total
// the same at every call of one precompute), and the pass's name. aerial itself draws no progress.
using ProgressCallback = std::function<void(int done, int total, std::string_view pass)>;

struct TableLoadOptions {
  std::filesystem::path cache_dir;  // empty: $AERIAL_CACHE_DIR, $XDG_CACHE_HOME/aerial or ~/.cache/aerial
  bool read_cache = true;           // false: always precompute
  bool write_cache = true;          // false: keep the tables in memory only
  // true: a cache that cannot be written is an error, reported before any work (when writing it
  // is the point, as for `aerial precompute`); false: a warning, and the tables are still used.
  bool require_cache_write = false;
  ProgressCallback progress;        // told of each precompute pass, if set
};

class TableSnapshot;

class Tables {
 public:
  // The tables of this atmosphere and these options: read from the cache when a file made for
  // exactly them by this version of aerial is there and intact (a version, a key and XXH64
  // checksums guard it), precomputed on the device otherwise and then written to the cache
  // atomically. A cache that cannot be written is a warning on stderr (unless
  // require_cache_write), and the tables still work; so is a damaged cache file, which is
  // recomputed, and a note says when stale temporaries of a killed write are removed.
  // Throws aerial::Error for invalid atmospheres or options, naming the field and the value.
  static Tables LoadOrPrecompute(const Device& device, const AtmosphereParameters& atmosphere,
                                 const PrecomputeOptions& options, const TableLoadOptions& load = {});
  // Reads a table file (Store, or `aerial precompute --out`) made for this atmosphere and options;
  // throws aerial::Error naming what is wrong with it (missing, truncated, another version or key,
  // a checksum).
  static Tables Load(const Device& device, const AtmosphereParameters& atmosphere,
                     const PrecomputeOptions& options, const std::filesystem::path& file);
  // Writes the tables to file, atomically (a temporary file, then a rename).
  void Store(const std::filesystem::path& file) const;
  // The tables in host memory, to move them to another device without a file (a background
  // thread precomputes on a device of its own, the renderer's device takes the result). Reads
  // the tables back and waits for the device.
  TableSnapshot Snapshot() const;
  static Tables FromSnapshot(const Device& device, const TableSnapshot& snapshot);

  ~Tables();
  Tables(Tables&&) noexcept;
  Tables& operator=(Tables&&) noexcept;

  const AtmosphereParameters& atmosphere() const;
  const PrecomputeOptions& options() const;
  bool from_cache() const;
  std::filesystem::path cache_file() const;  // where the cache is (empty with write_cache off)
  uint64_t gpu_bytes() const;
  // The GPU time of each precompute pass; empty when the tables were read from a file.
  const std::vector<PassTime>& precompute_times() const;

  // The AtmosphereBlock of shaders/include/definitions.glsl (set 0, binding 0 by the GLSL
  // contract; its C++ twin is aerial/shader_abi/atmosphere_block.h).
  UniformBlock atmosphere_block() const;
  // T(r, mu), 2D.
  SampledImage transmittance() const;
  // Ground irradiance E(r, mu_s), 2D.
  SampledImage irradiance() const;
  // Rayleigh (with multiple scattering folded in, in 4D) and single Mie scattering without phase:
  // 4D packed in 3D (x = nu * mu_s size + mu_s), or 3D.
  SampledImage rayleigh() const;
  SampledImage mie() const;
  // 3D variant: multiple scattering without phase (one texel in 4D, where it is in rayleigh()).
  SampledImage multiple() const;
  // The scattering density of orders >= 2 (J_ms), for marches along a segment, stored times
  // kMultipleDensityScale (shader_abi/atmosphere_block.h), in the tables' precision.
  SampledImage multiple_density() const;

  struct Impl;  // aerial's side (src/aerial/api/impl.h)

 private:
  friend struct ImplAccess;  // aerial's own code (src/aerial/api/impl.h)
  explicit Tables(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// Tables::Snapshot's result: the texels and what they were made for, table by table as the cache
// file holds them (each table's name and size are checked when a device takes them).
class TableSnapshot {
 public:
  ~TableSnapshot();
  TableSnapshot(TableSnapshot&&) noexcept;
  TableSnapshot& operator=(TableSnapshot&&) noexcept;
  const AtmosphereParameters& atmosphere() const;
  const PrecomputeOptions& options() const;

  struct Impl;  // aerial's side (src/aerial/api/impl.h)

 private:
  friend struct ImplAccess;  // aerial's own code (src/aerial/api/impl.h)
  friend class Tables;
  explicit TableSnapshot(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace aerial
