// aerial_bench_sky: the tables against the CPU reference with all orders, by region of sun zenith
// angle and camera altitude, per wavelength (aerial/validation/sky_accuracy.h): the figures of the
// docs/accuracy.md's "Accuracy against the physical sky". The reference takes minutes and is kept in
// --reference-file, so that several table configurations (--scattering-size, --orders,
// --series-tail ...) are compared against the same reference samples.
#include <cstdio>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "aerial/validation/sky_accuracy.h"
#include "aerial/cli/common_options.h"
#include "aerial/core/atomic_file.h"
#include "aerial/error.h"
#include "aerial/tables.h"
#include "bench_main.h"

namespace {

namespace validation = aerial::validation;

struct BenchOptions {
  aerial::cli::TableOptions tables;
  std::string grid = "full";
  int paths = 16384;
  std::string reference_file;
  std::string markdown_file;
  std::string samples_csv_file;
};

void Bench(const BenchOptions& cli) {
  aerial::AtmosphereParameters atmosphere = cli.tables.LoadAtmosphere();
  aerial::PrecomputeOptions options = cli.tables.MakePrecomputeOptions();
  // The reference here is at the atmosphere's three wavelengths; spectral tables are compared in
  // colour by aerial_bench_colour.
  if (options.colour != aerial::ColourMode::kRgb)
    throw aerial::Error("--colour", cli.tables.colour, "rgb (for spectral tables: aerial_bench_colour)");
  if (!cli.markdown_file.empty()) aerial::CheckWritable(cli.markdown_file);
  if (!cli.samples_csv_file.empty()) aerial::CheckWritable(cli.samples_csv_file);
  validation::SkyReference reference;
  if (!cli.reference_file.empty() && std::filesystem::exists(cli.reference_file)) {
    reference = validation::ReadSkyReference(cli.reference_file);
    if (reference.orders != options.RepresentedOrders())
      throw aerial::Error("--reference-file", cli.reference_file,
                          "a reference of the orders these tables stand for (made with other --orders or --series-tail)");
    std::fprintf(stderr, "reference: %zu samples from %s\n", reference.samples.size(), cli.reference_file.c_str());
  } else {
    validation::SkyGrid grid = cli.grid == "quick" ? validation::SkyGrid::Quick() : validation::SkyGrid::Full();
    reference = validation::ComputeSkyReference(
        atmosphere, grid, options.RepresentedOrders(), {.paths_per_query = cli.paths},
        [](size_t done, size_t total) {
          if (done % 100 == 0 || done == total) std::fprintf(stderr, "reference: %zu / %zu\n", done, total);
        });
    if (!cli.reference_file.empty()) validation::WriteSkyReference(reference, cli.reference_file);
  }
  aerial::Device device(cli.tables.MakeDeviceOptions());
  aerial::Tables tables = aerial::Tables::LoadOrPrecompute(device, atmosphere, options, cli.tables.MakeLoadOptions());
  std::vector<aerial::Spectrum> tables_values;
  auto regions = validation::CompareSkyWithTables(tables, reference, &tables_values);
  std::string table = validation::FormatSkyAccuracy(regions);
  std::fprintf(stderr, "%s\n", validation::FormatWorstSamples(regions).c_str());
  std::printf("tables: %s\nreference: %d paths per query, %s\n\n%s", options.Describe().c_str(),
              reference.paths_per_query,
              reference.orders == aerial::reference::kAllOrders ? "all orders" : ("orders 1.." + std::to_string(reference.orders)).c_str(),
              table.c_str());
  if (!cli.markdown_file.empty()) aerial::WriteFileAtomically(cli.markdown_file, table);
  if (!cli.samples_csv_file.empty())
    aerial::WriteFileAtomically(cli.samples_csv_file, validation::FormatSampleErrorsCsv(reference, tables_values));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"aerial_bench_sky: the tables against the CPU reference with all orders, by region and wavelength"};
  BenchOptions cli;
  // rgb unless asked: the reference is at the atmosphere's three wavelengths (Bench refuses the
  // spectral tables, aerial's default elsewhere).
  cli.tables.colour = "rgb";
  cli.tables.AddTo(app);
  app.add_option("--grid", cli.grid, "Views: full (~7400 reference queries) or quick (the test's grid)")
      ->check(CLI::IsMember({"full", "quick"}));
  app.add_option("--paths", cli.paths, "Reference paths per query")->check(CLI::Range(512, 1 << 24));
  app.add_option("--reference-file", cli.reference_file,
                 "Reference samples: read if the file exists, else computed and written there (JSON)");
  app.add_option("--markdown", cli.markdown_file, "Also write the table to this file");
  app.add_option("--samples-csv", cli.samples_csv_file,
                 "Also write every sample's reference and tables values and signed error to this file (CSV)");
  return aerial::bench::ParseAndRun(app, argc, argv, "aerial_bench_sky", [&] { Bench(cli); });
}
