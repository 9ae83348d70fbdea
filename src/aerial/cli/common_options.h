#pragma once
// Options shared by every command that uses tables: the atmosphere file, the table variant and
// resolution knobs, the cache, the Vulkan device.
#include <filesystem>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "aerial/atmosphere.h"
#include "aerial/core/memory_budget.h"
#include "aerial/device.h"
#include "aerial/tables.h"

namespace aerial::cli {

// The --help group of the table, device and memory options, listed after a command's own.
inline constexpr const char* kTableOptionsGroup = "Tables, device and memory";

struct TableOptions {
  std::filesystem::path atmosphere_file;
  std::string lut = "4d";
  // Spectral by default (docs/colour.md, "Defaults"). `probe` keeps rgb, whose channels are
  // wavelengths its JSON can name (probe_command.cpp); the library's PrecomputeOptions keep rgb,
  // so that an embedder's tables and their cost do not change under it.
  std::string colour = "spectral";
  std::optional<int> wavelengths;
  int orders = 4;
  std::string series_tail = "on";
  bool half_precision = false;
  std::string precision;  // empty: the variant's default
  bool small_tables = false;
  std::vector<int> transmittance_size;  // mu, r
  std::vector<int> irradiance_size;     // mu_s, r
  std::vector<int> scattering_size;     // r, mu, mu_s, nu
  std::vector<int> multiple_density_size;  // r, mu, mu_s, nu
  std::filesystem::path cache_dir;
  bool no_cache = false;
  std::string device;
  bool validation = false;
  bool quiet = false;
  std::optional<uint64_t> max_memory_mib;

  void AddTo(CLI::App& command);
  AtmosphereParameters LoadAtmosphere() const;
  PrecomputeOptions MakePrecomputeOptions() const;
  DeviceOptions MakeDeviceOptions() const;  // --device, --validation
  // --cache-dir, --no-cache; the progress bar unless --quiet.
  TableLoadOptions MakeLoadOptions() const;
  // The cache file of these tables (in --cache-dir, else the default directory), if any.
  std::optional<std::filesystem::path> CacheFile(const AtmosphereParameters& atmosphere,
                                                 const PrecomputeOptions& precompute) const;
  // --max-memory-mib, else the default budget or the device's heap when smaller.
  MemoryBudget MakeMemoryBudget(uint64_t largest_heap_bytes) const;
  // Before a device is chosen (loading the scene's models): --max-memory-mib, else the default.
  MemoryBudget MakeHostMemoryBudget() const;
};

}  // namespace aerial::cli
