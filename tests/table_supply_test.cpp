// CTest label "sanitizer": the table worker's hand-over between threads: run under the sanitizers too.
// The viewer's table supply (viewer/table_supply.h) with its background worker, without a window.
#include "aerial/viewer/table_supply.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <thread>

#include "gpu_fixture.h"

namespace aerial::viewer {
namespace {

// Waits (up to 2 minutes) until the worker has finished something, and takes it.
std::vector<std::unique_ptr<Tables>> WaitForFinished(TableSupply& supply, std::vector<std::string>& errors) {
  for (int i = 0; i < 1200; ++i) {
    if (!supply.status().busy) {
      std::vector<std::unique_ptr<Tables>> finished = supply.TakeFinished(testing::SharedDevice(), errors);
      if (!finished.empty() || !errors.empty()) return finished;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return {};
}

class TableSupplyTest : public testing::GpuTest {
 protected:
  // A supply whose panel may switch to `variants` (small tables), the 4D ones loaded at start.
  TableSupply MakeSupply(std::initializer_list<LutVariant> variants = {LutVariant::k4D}) {
    std::filesystem::path cache = std::filesystem::temp_directory_path() / "aerial-table-supply-test";
    std::map<LutVariant, PrecomputeOptions> options;
    for (LutVariant variant : variants) options[variant] = PrecomputeOptions::Small(variant);
    return TableSupply({.validation = true}, AtmosphereParameters::Earth(), options, {.cache_dir = cache},
                       LutVariant::k4D);
  }
};

// Knobs moved: the supply asks once for the new atmosphere, adopts its tables, and says when a
// variant cannot be had.
TEST_F(TableSupplyTest, AsksOnceAndAdoptsOnlyTheWantedAtmosphere) {
  TableSupply supply = MakeSupply();
  AtmosphereKnobs knobs = ReadKnobs(AtmosphereParameters::Earth());
  knobs.mie_g = 0.7;
  supply.Want(knobs);
  int asked = 0;
  auto missing = [&](LutVariant) { ++asked; return false; };
  EXPECT_TRUE(supply.Request({LutVariant::k4D}, missing).empty());
  EXPECT_TRUE(supply.Request({LutVariant::k4D}, missing).empty());  // already asked: not again
  std::vector<std::string> unavailable = supply.Request({LutVariant::k3D}, missing);
  ASSERT_EQ(unavailable.size(), 1u);
  EXPECT_NE(unavailable[0].find("3d"), std::string::npos) << unavailable[0];
  std::vector<std::string> errors;
  std::vector<std::unique_ptr<Tables>> finished = WaitForFinished(supply, errors);
  ASSERT_EQ(finished.size(), 1u) << (errors.empty() ? "" : errors[0]);
  EXPECT_TRUE(supply.IsWanted(*finished[0]));
  EXPECT_DOUBLE_EQ(finished[0]->atmosphere().mie_phase_g, 0.7);
}

// Tables asked for an atmosphere the knobs have since left are dropped. The worker takes requests
// in order, so when the tables asked second (3D, the knobs' new atmosphere) are taken, those asked
// first (4D, the atmosphere left) have been made and handed over before them: the supply must have
// dropped them, whatever the timing.
TEST_F(TableSupplyTest, DropsTablesOfAnAtmosphereLeftBeforeTheyCame) {
  TableSupply supply = MakeSupply({LutVariant::k4D, LutVariant::k3D});
  AtmosphereKnobs knobs = ReadKnobs(AtmosphereParameters::Earth());
  auto missing = [](LutVariant) { return false; };
  knobs.mie_g = 0.6;
  supply.Want(knobs);
  EXPECT_TRUE(supply.Request({LutVariant::k4D}, missing).empty());
  knobs.mie_g = 0.5;  // left before its tables came
  supply.Want(knobs);
  EXPECT_TRUE(supply.Request({LutVariant::k3D}, missing).empty());
  std::vector<std::string> errors;
  std::vector<std::unique_ptr<Tables>> finished = WaitForFinished(supply, errors);
  ASSERT_EQ(finished.size(), 1u) << (errors.empty() ? "" : errors[0]);
  EXPECT_EQ(finished[0]->options().variant, LutVariant::k3D);
  EXPECT_DOUBLE_EQ(finished[0]->atmosphere().mie_phase_g, 0.5);
}

}  // namespace
}  // namespace aerial::viewer
