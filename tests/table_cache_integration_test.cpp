// CTest label "sanitizer": the table cache's reads and writes: run under the sanitizers too.
// The table cache end to end: tables read back from the cache equal the computed ones, and a
// damaged, truncated or foreign file is detected, reported and rebuilt instead of used.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>

#include "aerial/error.h"
#include "aerial/precompute/table_store.h"
#include "gpu_fixture.h"

namespace aerial::testing {
namespace {

namespace fs = std::filesystem;

class TableCacheIntegration : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();
    dir_ = fs::temp_directory_path() / ("aerial-cache-test-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override {
    fs::remove_all(dir_);
    GpuTest::TearDown();
  }
  LoadedTables Load(const AtmosphereParameters& atmosphere = AtmosphereParameters::Earth()) {
    return LoadOrPrecompute(SharedContext(), atmosphere, PrecomputeOptions::Small(),
                            {.cache_dir = dir_});
  }
  fs::path dir_;
};

TEST_F(TableCacheIntegration, RoundTripGivesIdenticalTables) {
  LoadedTables computed = Load();
  ASSERT_FALSE(computed.from_cache);
  LoadedTables cached = Load();
  ASSERT_TRUE(cached.from_cache);
  TableCache a = computed.tables->Download();
  TableCache b = cached.tables->Download();
  ASSERT_EQ(a.tables.size(), b.tables.size());
  for (size_t i = 0; i < a.tables.size(); ++i)
    EXPECT_TRUE(a.tables[i].texels == b.tables[i].texels) << a.tables[i].name;
}

void FlipByte(const fs::path& file, std::streamoff offset) {
  std::fstream stream(file, std::ios::in | std::ios::out | std::ios::binary);
  stream.seekg(offset);
  char c = 0;
  stream.read(&c, 1);
  c = char(c ^ 0x5a);
  stream.seekp(offset);
  stream.write(&c, 1);
}

TEST_F(TableCacheIntegration, FlippedByteIsDetectedAndRebuilt) {
  LoadedTables first = Load();
  FlipByte(first.cache_file, std::streamoff(fs::file_size(first.cache_file) / 2));
  ::testing::internal::CaptureStderr();
  LoadedTables second = Load();
  std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_FALSE(second.from_cache);
  EXPECT_NE(log.find("ignoring table cache"), std::string::npos) << log;
  EXPECT_TRUE(Load().from_cache) << "the rebuilt file is valid again";
}

TEST_F(TableCacheIntegration, TruncatedFileIsDetectedAndRebuilt) {
  LoadedTables first = Load();
  fs::resize_file(first.cache_file, fs::file_size(first.cache_file) - 1000);
  ::testing::internal::CaptureStderr();
  LoadedTables second = Load();
  ::testing::internal::GetCapturedStderr();
  EXPECT_FALSE(second.from_cache);
}

TEST_F(TableCacheIntegration, FileFromAnotherParameterSetIsNotUsed) {
  LoadedTables earth = Load();
  AtmosphereParameters hazy = AtmosphereParameters::Earth();
  hazy.mie_scattering = {8e-6, 8e-6, 8e-6};
  hazy.mie_extinction = {9e-6, 9e-6, 9e-6};
  // Another parameter set gets its own file name; a file renamed into its place (as a stale or
  // foreign cache would be) carries the wrong key in its header and is rejected.
  fs::path hazy_file = CacheFilePath(dir_, hazy, PrecomputeOptions::Small());
  fs::copy_file(earth.cache_file, hazy_file);
  ::testing::internal::CaptureStderr();
  LoadedTables loaded = Load(hazy);
  std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_FALSE(loaded.from_cache);
  EXPECT_NE(log.find("cache key"), std::string::npos) << log;
}

// A cache write killed with -9 leaves its temporary (33 MB with the default tables) behind; the
// next use of the cache removes it once its writer is gone, and only then: while the writer holds
// its lock, whatever its pid (another pid namespace or host may run it).
TEST_F(TableCacheIntegration, TemporariesOfDeadWritersAreRemoved) {
  fs::create_directories(dir_);
  pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ASSERT_GT(dead, 0);
  ::waitpid(dead, nullptr, 0);  // reaped: its pid names no process now (until the system reuses it)
  auto temporary = [&](const std::string& target, pid_t pid, const std::string& random) {
    fs::path path = dir_ / (target + ".tmp-" + std::to_string(pid) + "-" + random);
    std::ofstream(path) << "half a cache";
    return path;
  };
  const std::string cache = "tables-4d-0123456789abcdef-0123456789abcdef.bin";
  fs::path stale = temporary(cache, dead, "0123456789abcdef");
  fs::path live = temporary(cache, dead, "0123456789abcdee");             // a write in progress
  int writer = ::open(live.c_str(), O_RDONLY | O_CLOEXEC);                 // as its writer holds it
  ASSERT_EQ(::flock(writer, LOCK_EX), 0);
  fs::path foreign = temporary("notes.txt", dead, "0123456789abcdef");     // not a cache file's
  fs::path unlike = temporary(cache, dead, "0123");                        // not our naming
  Load();
  ::close(writer);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(foreign));
  EXPECT_TRUE(fs::exists(unlike));
}

// The cache is optional. A FIFO at the cache file's name could block every command, and
// without HOME the cache could go to ./.aerial-cache; each is a warning and the tables are
// computed, unless writing the cache is the command's job (precompute), which fails naming it.
TEST_F(TableCacheIntegration, AFifoAtTheCacheFileIsSkipped) {
  fs::create_directories(dir_);
  fs::path cache = CacheFilePath(dir_, AtmosphereParameters::Earth(), PrecomputeOptions::Small());
  ASSERT_EQ(::mkfifo(cache.c_str(), 0600), 0);
  ::alarm(60);  // should the open regress, the test's process ends instead of hanging
  LoadedTables loaded = Load();
  ::alarm(0);
  EXPECT_FALSE(loaded.from_cache);
  EXPECT_TRUE(fs::is_fifo(cache));
}

TEST_F(TableCacheIntegration, ASymlinkLoopAtTheCacheFileIsSkipped) {
  fs::create_directories(dir_);
  fs::path cache = CacheFilePath(dir_, AtmosphereParameters::Earth(), PrecomputeOptions::Small());
  fs::create_symlink(dir_ / "loop", cache);
  fs::create_symlink(cache, dir_ / "loop");
  EXPECT_FALSE(Load().from_cache);  // threw "Too many levels of symbolic links" before
  EXPECT_TRUE(fs::is_symlink(cache));
}

TEST_F(TableCacheIntegration, WithoutHomeThereIsNoCache) {
  std::string home = std::getenv("HOME") ? std::getenv("HOME") : "";
  for (const char* name : {"HOME", "XDG_CACHE_HOME", "AERIAL_CACHE_DIR"}) ::unsetenv(name);
  TableStoreOptions store;
  LoadedTables loaded = LoadOrPrecompute(SharedContext(), AtmosphereParameters::Earth(), PrecomputeOptions::Small(), store);
  EXPECT_TRUE(loaded.cache_file.empty());
  EXPECT_FALSE(fs::exists(".aerial-cache"));
  store.require_cache_write = true;
  try {
    LoadOrPrecompute(SharedContext(), AtmosphereParameters::Earth(), PrecomputeOptions::Small(), store);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "HOME");
  }
  ::setenv("HOME", home.c_str(), 1);
}

}  // namespace
}  // namespace aerial::testing
