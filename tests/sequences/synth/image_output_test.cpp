#include <cmath>

#include <gtest/gtest.h>

#include "sequences/synth/image_output.hpp"

namespace facadeslam::synth {
namespace {

TEST(ImageOutput, NoiseHasTheRequestedSigmaAndZeroMean) {
  cv::Mat colour(240, 320, CV_32FC3, cv::Scalar(100, 100, 100));
  add_pixel_noise(colour, 3.0, 42, 0);
  cv::Scalar mean, sigma;
  cv::meanStdDev(colour.reshape(1), mean, sigma);
  EXPECT_NEAR(mean[0], 100.0, 0.02);
  EXPECT_NEAR(sigma[0], 3.0, 0.02);
  // Channels are independent: B and R noise uncorrelated.
  std::vector<cv::Mat> planes;
  cv::split(colour, planes);
  cv::Mat product = (planes[0] - 100.0).mul(planes[2] - 100.0);
  EXPECT_NEAR(cv::mean(product)[0] / 9.0, 0.0, 0.01);
}

TEST(ImageOutput, NoiseDependsOnSeedAndFrameOnly) {
  const cv::Mat base(8, 8, CV_32FC3, cv::Scalar(50, 60, 70));
  cv::Mat a = base.clone(), b = base.clone(), c = base.clone(), d = base.clone();
  add_pixel_noise(a, 2.0, 1, 5);
  add_pixel_noise(b, 2.0, 1, 5);
  add_pixel_noise(c, 2.0, 1, 6);
  add_pixel_noise(d, 2.0, 2, 5);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, d, cv::NORM_INF), 0.0);
  cv::Mat none = base.clone();
  add_pixel_noise(none, 0.0, 1, 5);
  EXPECT_EQ(cv::norm(none, base, cv::NORM_INF), 0.0);
}

TEST(ImageOutput, QuantiseRoundsAndClamps) {
  cv::Mat colour(1, 2, CV_32FC3);
  colour.at<cv::Vec3f>(0, 0) = {-3.f, 12.49f, 12.5f};
  colour.at<cv::Vec3f>(0, 1) = {254.6f, 300.f, 0.f};
  const cv::Mat q = quantise(colour);
  EXPECT_EQ(q.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 12, 13));
  EXPECT_EQ(q.at<cv::Vec3b>(0, 1), cv::Vec3b(255, 255, 0));
}

TEST(ImageOutput, DepthInRoundedMillimetresZeroForNoneOrTooFar) {
  cv::Mat depth(1, 5, CV_32FC1);
  depth.at<float>(0, 0) = 0.f;
  depth.at<float>(0, 1) = 1.2344f;
  depth.at<float>(0, 2) = 7.0006f;
  depth.at<float>(0, 3) = 65.5f;
  depth.at<float>(0, 4) = 65.535f;
  const cv::Mat mm = depth_millimetres(depth);
  ASSERT_EQ(mm.type(), CV_16UC1);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 0), 0);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 1), 1234);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 2), 7001);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 3), 65500);
  EXPECT_EQ(mm.at<std::uint16_t>(0, 4), 65535);
  depth.at<float>(0, 4) = 70.f;
  EXPECT_EQ(depth_millimetres(depth).at<std::uint16_t>(0, 4), 0);
}

}  // namespace
}  // namespace facadeslam::synth
