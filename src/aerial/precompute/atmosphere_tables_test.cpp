#include "aerial/precompute/atmosphere_tables.h"
#include "aerial/version.h"

#include <gtest/gtest.h>

namespace aerial {
namespace {

// A cache written by another release of aerial is not read: its key differs, so the tables are
// recomputed (table_cache.h rejects a file whose key is not the expected one).
TEST(TableCacheKey, DependsOnTheVersionOfAerial) {
  AtmosphereParameters earth = AtmosphereParameters::Earth();
  PrecomputeOptions options = PrecomputeOptions::Default();
  TableCacheKey this_release = MakeTableCacheKey(earth, options);
  EXPECT_EQ(this_release, MakeTableCacheKey(earth, options, AERIAL_VERSION));
  EXPECT_NE(this_release, MakeTableCacheKey(earth, options, "0.0.0-another"));
  EXPECT_EQ(this_release.atmosphere_hash, MakeTableCacheKey(earth, options, "0.0.0-another").atmosphere_hash);
}

}  // namespace
}  // namespace aerial
