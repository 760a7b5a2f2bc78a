#include "core/image/half_sample.hpp"

#include <gtest/gtest.h>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

TEST(HalfSample, AveragesEachTwoByTwoBlockWithRounding) {
  cv::Mat img = (cv::Mat_<std::uint8_t>(2, 4) << 0, 1, 10, 20, 1, 1, 30, 41);
  const cv::Mat half = half_sample(img);
  ASSERT_EQ(half.size(), cv::Size(2, 1));
  EXPECT_EQ(half.at<std::uint8_t>(0, 0), 1);   // 3/4 = 0.75 rounds to 1
  EXPECT_EQ(half.at<std::uint8_t>(0, 1), 25);  // 101/4 = 25.25
}

TEST(HalfSample, OddSizesDropTheLastRowAndColumn) {
  cv::Mat img(7, 9, CV_8UC1, cv::Scalar(200));
  EXPECT_EQ(half_sample(img).size(), cv::Size(4, 3));
}

TEST(HalfSample, RejectsColourImages) { EXPECT_THROW(half_sample(cv::Mat(8, 8, CV_8UC3)), Error); }

}  // namespace
}  // namespace facadeslam
