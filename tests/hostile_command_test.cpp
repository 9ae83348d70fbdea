// Hostile input as the command meets it: outputs that are not regular files,
// empty paths, a cache path that is wrong, a broken Vulkan driver manifest, and messages in
// aerial's own form. Each of these refusals comes before any GPU work; `timeout 30` turns a hang
// (a FIFO opened for reading or writing) into a failure. Each case failed before the fix: the
// note on each says how.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "aerial/atmosphere.h"
#include "aerial/precompute/table_store.h"
#include "hostile_command.h"

namespace aerial::testing {
namespace {

namespace fs = std::filesystem;

class HostileCommandRound2 : public HostileCommand {
 protected:
  HostileCommandRound2() : HostileCommand("hostile_command") {}
};

// Before: a FIFO or device at --stats was renamed over (as root, `--stats /dev/null` replaced
// /dev/null); the stats path's missing directories were created. (A link to /dev/null here, so
// that a regression replaces the link, not the device.)
TEST_F(HostileCommandRound2, StatsIntoASpecialFileOrAMissingDirectoryIsRefused) {
  fs::create_symlink("/dev/null", dir_ / "null");
  Expect("view --stats " + (dir_ / "null").string(), 1,
         {"--stats = " + (dir_ / "null").string(), "not a character device"});
  Expect("view --stats " + Fifo("fifo").string(), 1, {"not a FIFO (named pipe)"});
  fs::path missing = dir_ / "missing" / "dir" / "s.json";
  Expect("view --stats " + missing.string(), 1, {"--stats = " + missing.string(), "an existing directory"});
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
  EXPECT_TRUE(fs::is_symlink(dir_ / "null"));
}

// Before: a bad --shadows was found after --out's directory chain was made.
TEST_F(HostileCommandRound2, BenchChecksItsValuesBeforeMakingItsDirectory) {
  Expect("bench --shadows bad --out " + (dir_ / "a" / "b" / "c").string(), 1, {"--shadows = bad"});
  EXPECT_FALSE(fs::exists(dir_ / "a"));
}

// Before: an empty path read as "no path" and the command did nothing, with exit status 0.
TEST_F(HostileCommandRound2, EmptyPathsAreRefused) {
  for (const auto& [arguments, option] : {std::pair{"view --frames 1 --screenshot \"\"", "--screenshot"},
                                          std::pair{"view --stats \"\"", "--stats"},
                                          std::pair{"view --camera-path \"\"", "--camera-path"},
                                          std::pair{"render --scene \"\" --out x.png", "--scene"},
                                          std::pair{"render --out \"\"", "--out"}}) {
    Expect(arguments, 1, {"aerial: error: " + std::string(option) + " = (empty) is invalid; expected a path"});
  }
}

// Before: CLI11's own words ("Could not convert: ...", "Run with --help").
TEST_F(HostileCommandRound2, ParseErrorsAreInAerialsForm) {
  for (const std::string& arguments : {std::string("render --width abc --out x.png"), std::string("precompute --orders 20"),
                                       std::string("render --no-such-option --out x.png")}) {
    CommandRun run = Expect(arguments, 2, {});
    EXPECT_EQ(run.err.rfind("aerial: error: ", 0), 0u) << run.err;
  }
}

// Before: "--render-scale = 0.250000", and a range in other words than the check's.
TEST_F(HostileCommandRound2, ValuesAreShownAsWritten) {
  Expect("render --render-scale 0.2 --out x.png", 1, {"--render-scale = 0.2 is invalid; expected in [0.25, 1]"});
}

// Before: HOME unset put the cache in ./.aerial-cache without a word.
TEST_F(HostileCommandRound2, WithoutHomePrecomputeFailsNamingIt) {
  const std::string no_home = "env -u HOME -u XDG_CACHE_HOME -u AERIAL_CACHE_DIR";
  Expect("precompute --small-tables --quiet", 1, {"HOME = unset"}, no_home);
  EXPECT_FALSE(fs::exists(".aerial-cache"));
}

// Before: a FIFO at the cache file's name blocked every command.
TEST_F(HostileCommandRound2, FifoAtTheCacheFileFailsPrecomputeNamingIt) {
  fs::path cache = CacheFilePath(dir_.path(), AtmosphereParameters::Earth(), PrecomputeOptions::Small());
  ASSERT_EQ(::mkfifo(cache.c_str(), 0600), 0);
  // --colour rgb: the cache file of the library's default (rgb) small tables.
  Expect("precompute --small-tables --quiet --colour rgb --cache-dir " + dir_.path().string(), 1,
         {cache.string(), "not a FIFO (named pipe)"});
}

// Before: the world grid's volume was left out of the estimate (83 MiB for a 990 MB peak).
TEST_F(HostileCommandRound2, WorldGridCountsInTheMemoryBudget) {
  Expect("export-vdb --small-tables --quiet --world-grid 520 --max-memory-mib 500 --out " +
             (dir_ / "x.vdb").string(),
         1, {"--world-grid = 520 is invalid; expected sizes whose memory fits the budget"});
}

// Before: null in the probe's JSON and NaN pixels, with exit status 0.
TEST_F(HostileCommandRound2, NanTablesAreANamedError) {
  Expect("probe --small-tables --quiet --no-cache --orders 16 --atmosphere " AERIAL_SOURCE_DIR
         "/tests/data/hostile/thick_atmosphere.toml --altitude-m 1 --view-zenith-deg 45 --sun-zenith-deg 30 "
         "--azimuth-deg 0",
         1, {"precompute pass \"", "NaN or infinity in table"});
}

// Before: a malformed manifest read as "host memory ... lower --width/--height"; a FIFO hung
// the Vulkan loader.
TEST_F(HostileCommandRound2, BrokenDriverManifestIsNamed) {
  std::ofstream(dir_ / "bad_icd.json") << R"({"file_format_version": "1.0.0", "ICD": {)";
  for (const char* variable : {"VK_ICD_FILENAMES", "VK_DRIVER_FILES"}) {
    CommandRun run = Expect("precompute --small-tables --quiet --no-cache", 1,
                            {std::string(variable) + " = " + (dir_ / "bad_icd.json").string(), "Vulkan driver manifests"},
                            std::string("env ") + variable + "=" + (dir_ / "bad_icd.json").string());
    EXPECT_EQ(run.err.find("--width"), std::string::npos) << run.err;
  }
  fs::path fifo = Fifo("icd.json");
  Expect("precompute --small-tables --quiet --no-cache", 1, {"VK_ICD_FILENAMES = " + fifo.string(), "not a FIFO"},
         "env VK_ICD_FILENAMES=" + fifo.string());
}

}  // namespace
}  // namespace aerial::testing
