#include "aerial/precompute/table_store.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace aerial {
namespace {

// Sets (or, with nullopt, unsets) an environment variable for the scope, restoring it after.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    value ? ::setenv(name, value->c_str(), 1) : ::unsetenv(name);
  }
  ~ScopedEnvironment() { old_ ? ::setenv(name_, old_->c_str(), 1) : ::unsetenv(name_); }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// The XDG Base Directory Specification: a relative XDG_CACHE_HOME is ignored (and a relative HOME
// held to the same rule). Before, both put the cache in the working directory.
TEST(DefaultCacheDirectory, RelativeXdgCacheHomeAndHomeAreIgnored) {
  ScopedEnvironment aerial_dir("AERIAL_CACHE_DIR", std::nullopt);
  {
    ScopedEnvironment xdg("XDG_CACHE_HOME", "relative/cache"), home("HOME", "/home/someone");
    EXPECT_EQ(DefaultCacheDirectory(), std::filesystem::path("/home/someone/.cache/aerial"));
  }
  {
    ScopedEnvironment xdg("XDG_CACHE_HOME", "relative/cache"), home("HOME", "relative-home");
    EXPECT_EQ(DefaultCacheDirectory(), std::nullopt);
  }
  {
    ScopedEnvironment xdg("XDG_CACHE_HOME", "/var/cache/someone"), home("HOME", "relative-home");
    EXPECT_EQ(DefaultCacheDirectory(), std::filesystem::path("/var/cache/someone/aerial"));
  }
}

}  // namespace
}  // namespace aerial
