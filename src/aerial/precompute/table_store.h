#pragma once
// Tables for an atmosphere and options: read from the cache when a valid file for exactly these
// parameters exists, precomputed (and cached, atomically) otherwise. A corrupt, truncated or stale
// cache file is reported and rebuilt, never used. Temporaries that a killed cache write left in the
// cache directory are removed first (core/atomic_file.h, RemoveStaleTemporaries).
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "aerial/core/progress.h"
#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/vk/gpu_timer.h"

namespace aerial {

struct TableStoreOptions {
  std::filesystem::path cache_dir;  // empty: DefaultCacheDirectory()
  bool read_cache = true;           // false: always precompute (still writes the cache)
  bool write_cache = true;
  // true: an unwritable cache is an error, reported before any work (aerial precompute --out);
  // false: a cache that cannot be written (found before the work, or failing while written: a
  // full disk) is a warning, and the tables are used without being cached.
  bool require_cache_write = false;
  Progress::Observer progress;      // told of each precompute pass, if set; nothing is drawn
};

struct LoadedTables {
  std::unique_ptr<AtmosphereTables> tables;
  bool from_cache = false;
  std::filesystem::path cache_file;  // empty when there is no cache directory
  std::vector<vk::PassTime> pass_times;  // empty when read from the cache
};

// $AERIAL_CACHE_DIR, else $XDG_CACHE_HOME/aerial, else $HOME/.cache/aerial, where a relative
// XDG_CACHE_HOME or HOME counts as unset (the XDG Base Directory Specification); none when none of
// them is set (a cache in the working directory would surprise: the caller goes on without one).
std::optional<std::filesystem::path> DefaultCacheDirectory();

// One file per variant and parameter set: tables-<variant>-<atmosphere hash>-<options hash>.bin.
std::filesystem::path CacheFilePath(const std::filesystem::path& dir, const AtmosphereParameters&,
                                    const PrecomputeOptions&);

LoadedTables LoadOrPrecompute(const vk::Context& context, const AtmosphereParameters& atmosphere,
                              const PrecomputeOptions& options, const TableStoreOptions& store);

}  // namespace aerial
