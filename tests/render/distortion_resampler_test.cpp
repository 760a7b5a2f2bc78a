#include <cmath>

#include <gtest/gtest.h>

#include "render/distortion_resampler.hpp"

namespace facadeslam::render {
namespace {

Camera barrel_camera() {
  return Camera(
      320, 240,
      PinholeRadTan{.fx = 260, .fy = 255, .cx = 161.3, .cy = 118.2, .k1 = -0.3, .k2 = 0.1, .p1 = 0.001, .p2 = -0.0015});
}

TEST(DistortionResampler, OnlyDistortedCamerasAreResampled) {
  EXPECT_FALSE(needs_resampling(Camera(64, 48, PinholeRadTan{.fx = 50, .fy = 50, .cx = 31.5, .cy = 23.5})));
  EXPECT_TRUE(needs_resampling(barrel_camera()));
  EXPECT_FALSE(needs_resampling(Camera(64, 48, AtanCamera{.fx = 50, .fy = 50, .cx = 31.5, .cy = 23.5, .w = 0})));
  EXPECT_TRUE(needs_resampling(Camera(64, 48, AtanCamera{.fx = 50, .fy = 50, .cx = 31.5, .cy = 23.5, .w = 0.9})));
}

TEST(DistortionResampler, EachPixelSamplesItsOwnRayInsideTheVirtualImage) {
  for (const Camera& camera :
       {barrel_camera(), Camera(320, 240, AtanCamera{.fx = 250, .fy = 250, .cx = 159.5, .cy = 119.5, .w = 0.9})}) {
    const int margin = 2;
    const DistortionResampler resampler(camera, margin);
    const PinholeIntrinsics& v = resampler.virtual_camera();
    EXPECT_EQ(v.fx, camera.fx());  // same resolution at the centre
    for (int y = 0; y < camera.height(); y += 7)
      for (int x = 0; x < camera.width(); x += 5) {
        const Eigen::Vector2d expected = v.project(camera.unproject(Eigen::Vector2d(x, y)));
        const cv::Vec2d got = resampler.source(x, y);
        ASSERT_NEAR(got[0], expected.x(), 1e-9);
        ASSERT_NEAR(got[1], expected.y(), 1e-9);
        ASSERT_GE(got[0], margin - 1e-9);
        ASSERT_GE(got[1], margin - 1e-9);
        ASSERT_LE(got[0], v.width - 1 - margin);
        ASSERT_LE(got[1], v.height - 1 - margin);
      }
  }
}

TEST(DistortionResampler, BilinearResamplingOfALinearFunctionIsExact) {
  const DistortionResampler resampler(barrel_camera());
  const PinholeIntrinsics& v = resampler.virtual_camera();
  cv::Mat ramp(v.height, v.width, CV_32FC2);
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) ramp.at<cv::Vec2f>(y, x) = {0.5f * x + 3.f, 0.25f * y - 1.f};
  const cv::Mat out = resampler.resample_linear(ramp);
  ASSERT_EQ(out.size(), cv::Size(320, 240));
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x) {
      const cv::Vec2d s = resampler.source(x, y);
      ASSERT_NEAR(out.at<cv::Vec2f>(y, x)[0], 0.5 * s[0] + 3.0, 1e-3);
      ASSERT_NEAR(out.at<cv::Vec2f>(y, x)[1], 0.25 * s[1] - 1.0, 1e-3);
    }
}

TEST(DistortionResampler, BicubicResamplingOfAQuadraticIsExact) {
  // Catmull-Rom reproduces polynomials up to degree two.
  const DistortionResampler resampler(barrel_camera());
  const PinholeIntrinsics& v = resampler.virtual_camera();
  const auto f = [](double x, double y) { return 1e-3 * x * x - 2e-3 * x * y + 5e-4 * y * y + 0.3 * x + 7.0; };
  cv::Mat field(v.height, v.width, CV_32FC1);
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) field.at<float>(y, x) = static_cast<float>(f(x, y));
  const cv::Mat out = resampler.resample_cubic(field);
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x) {
      const cv::Vec2d s = resampler.source(x, y);
      ASSERT_NEAR(out.at<float>(y, x), f(s[0], s[1]), 2e-3);
    }
}

TEST(DistortionResampler, NearestResamplingTakesTheClosestPixel) {
  const DistortionResampler resampler(barrel_camera());
  const PinholeIntrinsics& v = resampler.virtual_camera();
  cv::Mat index(v.height, v.width, CV_32SC1);
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) index.at<int>(y, x) = y * v.width + x;
  const cv::Mat out = resampler.resample_nearest(index);
  for (int y = 0; y < out.rows; ++y)
    for (int x = 0; x < out.cols; ++x) {
      const cv::Vec2d s = resampler.source(x, y);
      const int i = out.at<int>(y, x);
      ASSERT_LE(std::abs(i % v.width - s[0]), 0.5 + 1e-9);
      ASSERT_LE(std::abs(i / v.width - s[1]), 0.5 + 1e-9);
    }
}

TEST(DistortionResampler, ReducesTheVirtualFocalLengthToFitTheSizeLimit) {
  const Camera fisheye(320, 240, AtanCamera{.fx = 150, .fy = 150, .cx = 159.5, .cy = 119.5, .w = 1.6});
  const DistortionResampler resampler(fisheye, 2, 600);
  EXPECT_LE(resampler.virtual_camera().width, 600);
  EXPECT_LE(resampler.virtual_camera().height, 600);
  EXPECT_LT(resampler.virtual_camera().fx, fisheye.fx());
}

}  // namespace
}  // namespace facadeslam::render
