#include "aerial/precompute/table_store.h"

#include <cstdio>
#include <cstdlib>

#include "aerial/core/atomic_file.h"
#include "aerial/core/progress.h"
#include "aerial/error.h"
#include "aerial/precompute/finite_tables.h"
#include "aerial/precompute/precomputer.h"

namespace aerial {

std::optional<std::filesystem::path> DefaultCacheDirectory() {
  if (const char* dir = std::getenv("AERIAL_CACHE_DIR"); dir && *dir) return dir;
  // The XDG Base Directory Specification: "All paths set in these environment variables must be
  // absolute. If an implementation encounters a relative path in any of these variables it should
  // consider the path invalid and ignore it." HOME is held to the same rule: a relative one would
  // put the cache wherever the command happens to run.
  auto absolute = [](const char* variable) -> std::optional<std::filesystem::path> {
    const char* value = std::getenv(variable);
    if (!value || value[0] != '/') return std::nullopt;
    return std::filesystem::path(value);
  };
  if (auto xdg = absolute("XDG_CACHE_HOME")) return *xdg / "aerial";
  if (auto home = absolute("HOME")) return *home / ".cache" / "aerial";
  return std::nullopt;
}

std::filesystem::path CacheFilePath(const std::filesystem::path& dir,
                                    const AtmosphereParameters& atmosphere,
                                    const PrecomputeOptions& options) {
  TableCacheKey key = MakeTableCacheKey(atmosphere, options);
  char name[96];
  std::snprintf(name, sizeof name, "tables-%s-%016llx-%016llx.bin", ToString(options.variant).c_str(),
                static_cast<unsigned long long>(key.atmosphere_hash),
                static_cast<unsigned long long>(key.options_hash));
  return dir / name;
}

LoadedTables LoadOrPrecompute(const vk::Context& context, const AtmosphereParameters& atmosphere,
                              const PrecomputeOptions& options, const TableStoreOptions& store) {
  options.Validate();
  LoadedTables loaded;
  loaded.tables = std::make_unique<AtmosphereTables>(context, atmosphere, options);
  // The cache is optional: anything wrong at its path only costs the next run its precompute,
  // and the command goes on without it (a warning naming what is wrong), unless writing it is the
  // command's job.
  bool use_cache = true;
  auto without_cache = [&](const Error& e) {
    if (store.require_cache_write) throw e;
    std::fprintf(stderr, "aerial: warning: not caching the tables (%s)\n", e.what());
    use_cache = false;
  };
  std::optional<std::filesystem::path> dir =
      store.cache_dir.empty() ? DefaultCacheDirectory() : store.cache_dir;
  if (const vk::TableFiltering filtering = context.table_filtering(); filtering != vk::TableFiltering::kSampler) {
    // Tables precomputed with reads that interpolate another way differ slightly: kept out of the
    // cache, which holds the sampler's.
    const std::string value = vk::ToString(filtering);
    if (store.require_cache_write)
      throw Error("AERIAL_TABLE_FILTERING", value, "unset: only tables read through the sampler are cached");
    std::fprintf(stderr, "aerial: AERIAL_TABLE_FILTERING=%s: the tables are precomputed, not cached\n", value.c_str());
    use_cache = false;
  } else if (!dir) {
    const char* home = std::getenv("HOME");
    // As a warning it reaches the user as it is, past the command line's option names (its error
    // messages get them): so it names neither an option nor an API field for the directory.
    without_cache(Error("HOME", home && *home ? home : "unset",
                        "an absolute path, or an absolute XDG_CACHE_HOME or AERIAL_CACHE_DIR, or a cache directory "
                        "given, to place the table cache (relative ones are ignored, as the XDG "
                        "specification says)"));
  } else {
    loaded.cache_file = CacheFilePath(*dir, atmosphere, options);
    for (const std::filesystem::path& stale : RemoveStaleTemporaries(*dir, "tables-"))
      std::fprintf(stderr, "aerial: removed %s, left by a table cache write that was killed\n",
                   Printable(stale.native()).c_str());
  }
  std::error_code ec;  // a symbolic link loop at the path: no cache to read, and writing fails below
  if (use_cache && store.read_cache && std::filesystem::exists(loaded.cache_file, ec)) {
    try {
      loaded.tables->Upload(ReadTableCache(loaded.cache_file, loaded.tables->cache_key()));
      loaded.from_cache = true;
      return loaded;
    } catch (const Error& e) {
      // Never use a damaged or stale file: say why, then rebuild it.
      std::fprintf(stderr, "aerial: ignoring table cache (%s); recomputing\n", e.what());
    }
  }
  if (use_cache && store.write_cache) {
    try {
      CheckWritable(loaded.cache_file);
    } catch (const Error& e) {
      without_cache(e);
    }
  }
  // Counted, never drawn: a caller shows progress its own way (the command line's bar is
  // cli/terminal_progress.h).
  Progress progress("precompute", PrecomputePassCount(options), /*out=*/nullptr);
  progress.set_observer(store.progress);
  loaded.pass_times = Precompute(*loaded.tables, &progress);
  TableCache texels = loaded.tables->Download();
  CheckFiniteTables(texels);
  if (use_cache && store.write_cache) {
    try {
      WriteTableCache(loaded.cache_file, texels);
    } catch (const Error& e) {
      without_cache(e);
    }
  }
  return loaded;
}

}  // namespace aerial
