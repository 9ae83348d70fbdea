#include "aerial/core/memory_budget.h"

#include <gtest/gtest.h>

#include "aerial/error.h"

namespace aerial {
namespace {

constexpr uint64_t kMiB = 1 << 20;

TEST(MemoryBudget, DefaultUnlessTheDeviceHasLessOrTheUserSaysOtherwise) {
  EXPECT_EQ(MakeMemoryBudget(std::nullopt, 24 * 1024 * kMiB).bytes, kDefaultMemoryBudgetMiB * kMiB);
  EXPECT_EQ(MakeMemoryBudget(std::nullopt, 1024 * kMiB).bytes, 1024 * kMiB);
  EXPECT_EQ(MakeMemoryBudget(8192, 1024 * kMiB).bytes, 8192 * kMiB) << "the user knows their machine";
}

TEST(MemoryBudget, ErrorNamesTheLargestUseWithTheEstimateAndTheBudget) {
  std::vector<MemoryUse> uses = {{"--scattering-size", "32,128,40,8", "tables", 100 * kMiB},
                                 {"--width/--height", "8192x8192", "render targets", 5000 * kMiB}};
  MemoryBudget budget = MakeMemoryBudget(std::nullopt, 24 * 1024 * kMiB);
  try {
    budget.Check(uses);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.field(), "--width/--height");
    EXPECT_EQ(e.value(), "8192x8192");
    EXPECT_NE(e.allowed().find("estimated 5100.0 MiB (--scattering-size 32,128,40,8: tables 100.0 MiB; "
                               "--width/--height 8192x8192: render targets 5000.0 MiB) > budget 2048.0 MiB"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(MakeMemoryBudget(5100, 0).Check(uses)) << "a budget the estimate fits";
}

}  // namespace
}  // namespace aerial
