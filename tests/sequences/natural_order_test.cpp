#include "sequences/natural_order.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace facadeslam {
namespace {

TEST(NaturalOrder, DigitRunsCompareAsNumbers) {
  EXPECT_TRUE(natural_less("frame2.png", "frame10.png"));
  EXPECT_FALSE(natural_less("frame10.png", "frame2.png"));
  EXPECT_TRUE(natural_less("a9b", "a10a"));
}

TEST(NaturalOrder, SortsAMixedListAsPeopleExpect) {
  std::vector<std::string> names = {"img10.png", "img1.png", "IMG3.png", "img2.png", "img02.png", "a.png"};
  std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) { return natural_less(a, b); });
  const std::vector<std::string> expected = {"a.png", "img1.png", "img2.png", "img02.png", "IMG3.png", "img10.png"};
  EXPECT_EQ(names, expected);
}

TEST(NaturalOrder, IsIrreflexiveAndBreaksTiesDeterministically) {
  EXPECT_FALSE(natural_less("x1", "x1"));
  // Equal under case-folding: exactly one order holds.
  EXPECT_NE(natural_less("Frame", "frame"), natural_less("frame", "Frame"));
}

TEST(NaturalOrder, VeryLongDigitRunsDoNotOverflow) {
  EXPECT_TRUE(natural_less("t99999999999999999999999", "t100000000000000000000000"));
}

}  // namespace
}  // namespace facadeslam
