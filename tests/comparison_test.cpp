// WorstError's sample count: a comparison whose expected values all fall below the floor reports
// a worst error of 0, which only the count can catch.
#include <gtest/gtest.h>

#include "comparison.h"

namespace aerial::testing {
namespace {

TEST(Comparison, NoSampleAboveTheFloorFailsTheCount) {
  WorstError worst(1e-3);
  worst.Add(2e-4, 1e-4, "below the floor");  // 100% off, but not compared
  EXPECT_EQ(worst.value(), 0.0);
  EXPECT_FALSE(ComparedExactly(worst, 1));
  EXPECT_FALSE(ComparedAtLeast(worst, 1));
  EXPECT_TRUE(ComparedExactly(worst, 0));
}

TEST(Comparison, CountsEverySampleAtOrAboveTheFloor) {
  WorstError worst(1e-3);
  worst.Add(1e-3, 1e-3, "at the floor");
  worst.Add(Spectrum{1.0, 2e-4, 1.01}, Spectrum{1.0, 1e-4, 1.0}, "a spectrum, green below the floor");
  EXPECT_TRUE(ComparedExactly(worst, 3));
  EXPECT_TRUE(ComparedAtLeast(worst, 3));
  EXPECT_FALSE(ComparedAtLeast(worst, 4));
  EXPECT_FALSE(ComparedExactly(worst, 2));
  EXPECT_NEAR(worst.value(), 0.01, 1e-12);
}

}  // namespace
}  // namespace aerial::testing
