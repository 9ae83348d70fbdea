// aerial_bench_colour: the tables' colour against the spectral CPU reference at 48 wavelengths
// (validation/colour_accuracy.h): chromaticity distance du'v' and relative luminance error of the
// sky radiance, the radiance to a point 10 km away, the sky irradiance and the sun's irradiance,
// by sun band and camera altitude, for rgb and spectral tables side by side (docs/colour.md). The
// reference takes hours and is kept in --reference-file (tests/data/colour_reference.json), written
// after each of its samples so that a run cut short continues where it stopped.
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "aerial/cli/common_options.h"
#include "aerial/error.h"
#include "aerial/tables.h"
#include "aerial/validation/colour_accuracy.h"
#include "bench_main.h"

namespace {

using aerial::validation::ColourReference;

struct BenchOptions {
  aerial::cli::TableOptions tables;
  std::string reference_file;
  // 32768 paths: at 48 wavelengths a standard error of ~0.0002 in u'v' for a daylight sky.
  int paths = 32768;
  bool held_only = false;
};

void Bench(const BenchOptions& cli) {
  const aerial::AtmosphereParameters atmosphere = cli.tables.LoadAtmosphere();
  aerial::PrecomputeOptions spectral = cli.tables.MakePrecomputeOptions();
  spectral.colour = aerial::ColourMode::kSpectral;
  aerial::PrecomputeOptions rgb = spectral;
  rgb.colour = aerial::ColourMode::kRgb;

  // A file cut short (the reference takes hours) is continued from its last sample: each sample is
  // written as it is made.
  ColourReference reference{.orders = spectral.RepresentedOrders(), .paths_per_query = cli.paths};
  if (cli.held_only && (cli.reference_file.empty() || !std::filesystem::exists(cli.reference_file)))
    throw aerial::Error("--held-only", "set", "with the --reference-file of a reference computed before");
  if (!cli.reference_file.empty() && std::filesystem::exists(cli.reference_file)) {
    reference = aerial::validation::ReadColourReference(cli.reference_file);
    if (reference.orders != spectral.RepresentedOrders())
      throw aerial::Error("--reference-file", cli.reference_file, "a reference of the tables' orders (--orders)");
  }
  if (!aerial::validation::IsComplete(reference) && !cli.held_only) {
    if (!reference.samples.empty())
      std::fprintf(stderr, "reference: continuing %s after its %zu samples (%d paths per query)\n",
                   cli.reference_file.c_str(), reference.samples.size(), reference.paths_per_query);
    aerial::validation::ContinueColourReference(
        atmosphere, reference,
        [](size_t done, size_t total, int paths) {
          std::fprintf(stderr, "reference: %zu / %zu (%d paths)\n", done, total, paths);
        },
        [&](const ColourReference& so_far) {
          if (!cli.reference_file.empty()) aerial::validation::WriteColourReference(so_far, cli.reference_file);
        });
  }

  aerial::Device device(cli.tables.MakeDeviceOptions());
  std::printf("reference: %d wavelengths over 360-830 nm (midpoint rule), all orders; %zu of %zu views\n\n",
              reference.wavelengths, reference.samples.size(), aerial::validation::ColourReferenceViewCount());
  for (const aerial::PrecomputeOptions& options : {rgb, spectral}) {
    aerial::Tables tables =
        aerial::Tables::LoadOrPrecompute(device, atmosphere, options, cli.tables.MakeLoadOptions());
    std::printf("%s\n", aerial::validation::FormatColourAccuracy(
                            aerial::ToString(options.colour),
                            aerial::validation::CompareColourWithTables(tables, reference))
                            .c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"aerial_bench_colour: rgb and spectral tables against the spectral CPU reference, in colour"};
  BenchOptions cli;
  cli.tables.AddTo(app);
  app.add_option("--paths", cli.paths, "Reference paths per query")->check(CLI::Range(512, 1 << 24));
  app.add_option("--reference-file", cli.reference_file,
                 "Reference values: read if the file exists (continued if it was cut short), else computed and written there (JSON)");
  app.add_flag("--held-only", cli.held_only,
               "Compare with the views the reference file holds, without computing the others");
  return aerial::bench::ParseAndRun(app, argc, argv, "aerial_bench_colour", [&] { Bench(cli); });
}
