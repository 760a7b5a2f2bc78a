// FACADESLAM_ASSERT: a broken invariant stops the program with where and
// what on stderr, in every build type; a holding one costs nothing visible.
#include "core/util/assert.hpp"

#include <gtest/gtest.h>

namespace facadeslam {
namespace {

int checked_half(int even) {
  FACADESLAM_ASSERT(even % 2 == 0, "halved numbers are even");
  return even / 2;
}

TEST(AssertDeathTest, ABrokenInvariantAbortsNamingWhereAndWhat) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EQ(checked_half(8), 4);
  EXPECT_DEATH(checked_half(7), "internal error at .*assert_test.cpp:[0-9]+: halved numbers are even \\(even % 2 == 0");
}

}  // namespace
}  // namespace facadeslam
