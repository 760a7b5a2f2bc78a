#include "sequences/video_timestamps.hpp"

#include <limits>

#include <gtest/gtest.h>

namespace facadeslam {
namespace {

TEST(VideoTimestamps, SaneDecoderPositionsAreUsed) {
  VideoTimestamps clock(25.0);
  EXPECT_DOUBLE_EQ(clock.next(0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(clock.next(1, 33.0), 0.033);  // not 1/25: the decoder knows better
  EXPECT_DOUBLE_EQ(clock.next(3, 100.0), 0.1);
  EXPECT_TRUE(clock.using_positions());
}

TEST(VideoTimestamps, PositionsStuckAtZeroFallBackToTheFrameRate) {
  VideoTimestamps clock(10.0);
  EXPECT_DOUBLE_EQ(clock.next(0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(clock.next(1, 0.0), 0.1);
  EXPECT_FALSE(clock.using_positions());
  EXPECT_DOUBLE_EQ(clock.next(4, 0.0), 0.4);
}

TEST(VideoTimestamps, NonFinitePositionFromTheStartUsesIndexOverRate) {
  VideoTimestamps clock(20.0);
  EXPECT_DOUBLE_EQ(clock.next(2, std::numeric_limits<double>::quiet_NaN()), 0.1);
  EXPECT_DOUBLE_EQ(clock.next(3, 150.0), 0.15) << "once unusable, positions are not trusted again";
}

TEST(VideoTimestamps, PositionGoingBackwardsContinuesFromTheLastGoodTimestamp) {
  VideoTimestamps clock(10.0);
  EXPECT_DOUBLE_EQ(clock.next(0, 5000.0), 5.0);
  EXPECT_DOUBLE_EQ(clock.next(1, 5100.0), 5.1);
  EXPECT_DOUBLE_EQ(clock.next(2, 200.0), 5.2);
  EXPECT_DOUBLE_EQ(clock.next(4, -1.0), 5.4);
}

TEST(VideoTimestamps, NegativeFirstPositionIsNotUsed) {
  VideoTimestamps clock(10.0);
  EXPECT_DOUBLE_EQ(clock.next(0, -40.0), 0.0);
  EXPECT_FALSE(clock.using_positions());
}

}  // namespace
}  // namespace facadeslam
