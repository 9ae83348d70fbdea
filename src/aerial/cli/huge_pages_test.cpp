#include "aerial/cli/huge_pages.h"

#include <gtest/gtest.h>

namespace aerial::cli {
namespace {

TEST(HugePages, TunableAddedOnceAndTheUsersChoiceKept) {
  EXPECT_EQ(TunablesWithHugePages(nullptr), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(TunablesWithHugePages(""), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(TunablesWithHugePages("glibc.malloc.check=3"), "glibc.malloc.check=3:glibc.malloc.hugetlb=1");
  EXPECT_EQ(TunablesWithHugePages("glibc.malloc.hugetlb=1"), std::nullopt) << "started again already";
  EXPECT_EQ(TunablesWithHugePages("glibc.malloc.check=3:glibc.malloc.hugetlb=0"), std::nullopt)
      << "the user's choice";
}

}  // namespace
}  // namespace aerial::cli
