#include "aerial/cli/common_options.h"

#include "aerial/atmosphere.h"
#include "aerial/cli/path_option.h"
#include "aerial/cli/terminal_progress.h"
#include "aerial/error.h"
#include "aerial/precompute/table_store.h"

namespace aerial::cli {

void TableOptions::AddTo(CLI::App& command) {
  // Listed after the command's own options, in a group of their own: most runs leave them alone.
  command.option_defaults()->group(kTableOptionsGroup);
  AddPathOption(command, "--atmosphere", atmosphere_file,
                     "Atmosphere parameters (TOML); default: the built-in \"earth\"");
  command.add_option("--lut", lut, "Scattering table variant: 4d (r, mu, mu_s, nu) or 3d (nu dropped)")
      ->check(CLI::IsMember({"4d", "3d"}));
  command.add_option("--colour", colour,
                     "What the tables' channels hold: rgb (radiance at the atmosphere's three wavelengths) "
                     "or spectral (--wavelengths over 360-830 nm, converted to linear sRGB with the CIE "
                     "1931 observer); default " + colour)
      ->check(CLI::IsMember({"rgb", "spectral"}));
  command.add_option("--wavelengths", wavelengths,
                     "Wavelengths of --colour spectral: a multiple of 6 in [6, 48] (default 12; every other one gets its own orders >= 2)");
  command.add_option("--orders", orders, "Scattering orders to precompute (1-16)")->check(CLI::Range(1, 16));
  command.add_option("--series-tail", series_tail,
                     "After the last order, add the orders beyond it as a geometric series: on (default; "
                     "the whole series) or off (exactly orders 1..N)")
      ->check(CLI::IsMember({"on", "off"}));
  command.add_option("--precision", precision,
                     "Scattering tables' floats: float16 or float32 (default: float16 for the 4D "
                     "tables, float32 for the 3D and the small ones)")
      ->check(CLI::IsMember({"float16", "float32"}));
  command.add_flag("--half", half_precision, "Store the scattering tables as 16-bit floats (--precision float16)");
  command.add_flag("--small-tables", small_tables, "Quarter-resolution tables (tests, quick looks)");
  command.add_option("--transmittance-size", transmittance_size, "Transmittance table MU,R (default 256,64)")
      ->delimiter(',')->expected(2)->default_str("");
  command.add_option("--irradiance-size", irradiance_size, "Irradiance table MU_S,R (default 64,32)")
      ->delimiter(',')->expected(2)->default_str("");
  command.add_option("--scattering-size", scattering_size,
                     "Scattering table R,MU,MU_S,NU (default 32,128,36,9; NU must be 1 with --lut 3d)")
      ->delimiter(',')->expected(4)->default_str("");
  command.add_option("--multiple-density-size", multiple_density_size,
                     "Multiple scattering density table R,MU,MU_S,NU (default 32,64,36,9; NU must be 1 "
                     "with --lut 3d)")
      ->delimiter(',')->expected(4)->default_str("");
  AddPathOption(command, "--cache-dir", cache_dir, "Table cache directory (default ~/.cache/aerial)");
  command.add_flag("--no-cache", no_cache, "Recompute the tables even when a cached copy exists");
  command.add_option("--device", device, "Vulkan device to use: part of its name (or AERIAL_DEVICE)");
  command.add_flag("--validation", validation, "Enable the Vulkan validation layers (or AERIAL_VALIDATION=1)");
  command.add_option("--max-memory-mib", max_memory_mib,
                     "Memory budget for tables, froxels and images, checked before allocating (default " +
                         std::to_string(kDefaultMemoryBudgetMiB) + ", or the device's memory if smaller)")
      ->check(CLI::Range(uint64_t{1}, uint64_t{1} << 30));
  command.option_defaults()->group("Options");
  command.add_flag("--quiet", quiet, "No progress bar");
}

AtmosphereParameters TableOptions::LoadAtmosphere() const {
  return atmosphere_file.empty() ? AtmosphereParameters::Earth() : LoadAtmosphereFile(atmosphere_file);
}

PrecomputeOptions TableOptions::MakePrecomputeOptions() const {
  LutVariant variant = ParseLutVariant(lut, "--lut");
  PrecomputeOptions options =
      small_tables ? PrecomputeOptions::Small(variant) : PrecomputeOptions::Default(variant);
  if (!transmittance_size.empty()) {
    options.resolution.transmittance_mu = transmittance_size[0];
    options.resolution.transmittance_r = transmittance_size[1];
  }
  if (!irradiance_size.empty()) {
    options.resolution.irradiance_mu_s = irradiance_size[0];
    options.resolution.irradiance_r = irradiance_size[1];
  }
  if (!scattering_size.empty()) {
    options.SetScatteringSize(scattering_size[0], scattering_size[1], scattering_size[2],
                              scattering_size[3]);
  }
  if (!multiple_density_size.empty()) {
    options.resolution.multiple_density_r = multiple_density_size[0];
    options.resolution.multiple_density_mu = multiple_density_size[1];
    options.resolution.multiple_density_mu_s = multiple_density_size[2];
    options.resolution.multiple_density_nu = multiple_density_size[3];
  }
  options.orders = orders;
  options.colour = ParseColourMode(colour, "--colour");
  if (wavelengths) {
    if (options.colour != ColourMode::kSpectral)
      throw Error("--wavelengths", std::to_string(*wavelengths), "only with --colour spectral");
    options.spectral_wavelengths = *wavelengths;
  }
  options.close_series = series_tail == "on";
  if (half_precision && precision == "float32")
    throw Error("--precision", "float32 with --half", "float16 with --half (--half means float16), or no --half");
  if (half_precision) options.precision = TablePrecision::kFloat16;
  if (!precision.empty()) options.precision = ParseTablePrecision(precision, "--precision");
  options.Validate();
  return options;
}

DeviceOptions TableOptions::MakeDeviceOptions() const { return {.device_name = device, .validation = validation}; }

TableLoadOptions TableOptions::MakeLoadOptions() const {
  return {.cache_dir = cache_dir,
          .read_cache = !no_cache,
          .write_cache = true,
          .progress = quiet ? ProgressCallback() : TerminalProgress("precompute " + lut)};
}

std::optional<std::filesystem::path> TableOptions::CacheFile(const AtmosphereParameters& atmosphere,
                                                            const PrecomputeOptions& precompute) const {
  std::optional<std::filesystem::path> dir = cache_dir.empty() ? DefaultCacheDirectory() : cache_dir;
  if (!dir) return std::nullopt;
  return CacheFilePath(*dir, atmosphere, precompute);
}

MemoryBudget TableOptions::MakeMemoryBudget(uint64_t largest_heap_bytes) const {
  MemoryBudget budget = aerial::MakeMemoryBudget(max_memory_mib, largest_heap_bytes);
  // Where it comes from in the command's words: the option that sets it.
  budget.origin = max_memory_mib ? "--max-memory-mib " + std::to_string(*max_memory_mib)
                                 : budget.origin + "; --max-memory-mib N sets another";
  return budget;
}

MemoryBudget TableOptions::MakeHostMemoryBudget() const { return MakeMemoryBudget(UINT64_MAX); }

}  // namespace aerial::cli
