#include "core/plot/ticks.hpp"

#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace facadeslam::plot {
namespace {

using ::testing::DoubleNear;
using ::testing::ElementsAre;

TEST(NiceTicks, UnitRange) {
  const auto t = nice_ticks(0.0, 0.93);
  EXPECT_DOUBLE_EQ(t.step, 0.2);
  EXPECT_DOUBLE_EQ(t.lo, 0.0);
  EXPECT_DOUBLE_EQ(t.hi, 1.0);
  EXPECT_THAT(t.values, ElementsAre(DoubleNear(0.0, 1e-12), DoubleNear(0.2, 1e-12), DoubleNear(0.4, 1e-12),
                                    DoubleNear(0.6, 1e-12), DoubleNear(0.8, 1e-12), DoubleNear(1.0, 1e-12)));
}

TEST(NiceTicks, NegativeToPositiveWithStepFive) {
  const auto t = nice_ticks(-3.7, 12.2);
  EXPECT_DOUBLE_EQ(t.step, 5.0);
  EXPECT_THAT(t.values, ElementsAre(-5.0, 0.0, 5.0, 10.0, 15.0));
}

TEST(NiceTicks, StepsAreOneTwoOrFiveTimesAPowerOfTen) {
  for (const double span : {0.0013, 0.07, 0.3, 1.0, 4.2, 17.0, 380.0, 9.9e5}) {
    const auto t = nice_ticks(1.0, 1.0 + span);
    const double mantissa = t.step / std::pow(10.0, std::floor(std::log10(t.step)));
    EXPECT_TRUE(std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 || std::abs(mantissa - 5.0) < 1e-9)
        << "span " << span << " step " << t.step;
    EXPECT_LE(t.lo, 1.0);
    EXPECT_GE(t.hi, 1.0 + span);
    EXPECT_GE(t.values.size(), 3u);
    EXPECT_LE(t.values.size(), 12u);
  }
}

TEST(NiceTicks, EndsThatAreTicksAddNoExtraTick) {
  const auto t = nice_ticks(0.0, 0.6000000000000001);  // 3 * 0.2 in floating point
  EXPECT_NEAR(t.hi, 0.6, 1e-12);
}

TEST(NiceTicks, ReversedRangeIsTheSame) { EXPECT_EQ(nice_ticks(10.0, 2.0).values, nice_ticks(2.0, 10.0).values); }

TEST(NiceTicks, ConstantValueGetsARangeAroundIt) {
  const auto t = nice_ticks(5.0, 5.0);
  EXPECT_LT(t.lo, 5.0);
  EXPECT_GT(t.hi, 5.0);
  const auto z = nice_ticks(0.0, 0.0);
  EXPECT_LT(z.lo, 0.0);
  EXPECT_GT(z.hi, 0.0);
}

TEST(NiceTicks, NonFiniteRangeIsAnError) {
  EXPECT_THROW(nice_ticks(0.0, std::numeric_limits<double>::infinity()), Error);
  EXPECT_THROW(nice_ticks(std::numeric_limits<double>::quiet_NaN(), 1.0), Error);
  EXPECT_THROW(nice_ticks(0.0, 1.0, 1), Error);
}

TEST(FormatTick, DecimalsFollowTheStep) {
  EXPECT_EQ(format_tick(0.2000000001, 0.2), "0.2");
  EXPECT_EQ(format_tick(10.0, 5.0), "10");
  EXPECT_EQ(format_tick(-0.05, 0.05), "-0.05");
  EXPECT_EQ(format_tick(1500.0, 500.0), "1500");
  EXPECT_EQ(format_tick(-1e-17, 0.5), "0.0");  // never "-0.0"
  EXPECT_EQ(format_tick(2e8, 1e8), "2e+08");
}

}  // namespace
}  // namespace facadeslam::plot
