// aerial precompute: build (or validate) the cached tables and report the GPU time of each pass.
#include <cstdio>
#include <memory>

#include "aerial/cli/commands.h"
#include "aerial/cli/common_options.h"
#include "aerial/cli/memory_uses.h"
#include "aerial/core/output_conflicts.h"
#include "aerial/error.h"

namespace aerial::cli {

void AddPrecomputeCommand(CLI::App& app) {
  auto options = std::make_shared<TableOptions>();
  CLI::App* command = app.add_subcommand("precompute", "Precompute the atmosphere tables into the cache");
  options->AddTo(*command);
  command->callback([options] {
    AtmosphereParameters atmosphere = options->LoadAtmosphere();
    PrecomputeOptions precompute = options->MakePrecomputeOptions();
    if (std::optional<std::filesystem::path> cache = options->CacheFile(atmosphere, precompute))
      CheckOutputConflicts({{"table cache", *cache}});
    Device device(options->MakeDeviceOptions());
    options->MakeMemoryBudget(device.largest_heap_bytes()).Check(TableMemoryUses(precompute));
    TableLoadOptions load = options->MakeLoadOptions();
    load.require_cache_write = true;
    Tables tables = Tables::LoadOrPrecompute(device, atmosphere, precompute, load);
    std::printf("device: %s\ntables: %s (%s)\n", device.name().c_str(), tables.options().Describe().c_str(),
                Printable(atmosphere.name).c_str());
    std::printf("table memory: %.2f MiB\n", double(tables.gpu_bytes()) / (1 << 20));
    if (tables.from_cache()) {
      std::printf("cache: %s (valid, reused; --no-cache recomputes)\n", Printable(tables.cache_file().native()).c_str());
      return;
    }
    std::printf("cache: %s (written)\nGPU time per pass:\n", Printable(tables.cache_file().native()).c_str());
    double total = 0.0;
    for (const auto& pass : tables.precompute_times()) {
      std::printf("  %-36s %10.1f ms\n", pass.pass.c_str(), pass.milliseconds);
      total += pass.milliseconds;
    }
    std::printf("  %-36s %10.1f ms\n", "total", total);
  });
}

}  // namespace aerial::cli
