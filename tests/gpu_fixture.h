#pragma once
// Shared GPU state for the cross-module tests: one Vulkan context with validation on, and table
// sets that are precomputed once and then read from the test cache (AERIAL_CACHE_DIR, set by
// tests/test_environment.cpp), since every test runs in its own process. Every GPU test derives from GpuTest, which
// fails the test if the validation layers printed anything while it ran.
#include <gtest/gtest.h>

#include "aerial/image.h"
#include "aerial/precompute/table_store.h"
#include "aerial/tables.h"
#include "aerial/vk/context.h"
#include "aerial/vk/resources.h"

namespace aerial::testing {

vk::Context& SharedContext();

// Earth's tables for these options, precomputed once per process or read from the test cache.
const AtmosphereTables& CachedTables(const PrecomputeOptions& options);
// Default resolutions (256x64, 64x32, R32 MU128 MU_S36 NU8, or NU1 for 3D), float32.
const AtmosphereTables& FullTables(int orders = 4, LutVariant variant = LutVariant::k4D);
// Quarter-size tables for tests that check structure rather than accuracy.
const AtmosphereTables& SmallTables(LutVariant variant = LutVariant::k4D);

// The shared context as the public API's Device (aerial/device.h), and the small tables through
// it (from the test cache, like SmallTables), for tests of what is built on the public API.
const Device& SharedDevice();
const aerial::Tables& SmallPublicTables();

// An rgba32f image holding the image's pixels, in the GENERAL layout, written before it returns.
vk::Image Upload(const ImageRgbF& image);

// The image's texels, as stored (x fastest, then y, then z), read back through a staging buffer.
std::vector<std::byte> ReadBack(const vk::Image& image);

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

 private:
  int validation_messages_before_ = 0;
};

}  // namespace aerial::testing
