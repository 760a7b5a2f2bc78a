#include <gtest/gtest.h>

#include "core/image/black_body.hpp"
#include "sequences/synth/lighting.hpp"

namespace facadeslam::synth {
namespace {

TEST(Lighting, ReferenceTemperatureIsNeutral) {
  const cv::Vec3d g = black_body_gains_bgr(6500.0);
  EXPECT_NEAR(g[0], 1.0, 1e-12);
  EXPECT_NEAR(g[1], 1.0, 1e-12);
  EXPECT_NEAR(g[2], 1.0, 1e-12);
}

TEST(Lighting, LowTemperaturesAreWarmHighOnesBlue) {
  const cv::Vec3d warm = black_body_gains_bgr(3800.0), blue = black_body_gains_bgr(12000.0);
  EXPECT_DOUBLE_EQ(warm[1], 1.0);  // green keeps its value
  EXPECT_GT(warm[2], 1.2);         // red up
  EXPECT_LT(warm[0], 0.7);         // blue down
  EXPECT_LT(blue[2], 1.0);
  EXPECT_GT(blue[0], 1.0);
  // Monotonic in temperature.
  EXPECT_GT(black_body_gains_bgr(3000.0)[2], warm[2]);
}

TEST(Lighting, KeysInterpolateAndHoldAtTheEnds) {
  const std::vector<LightingKey> keys = {{1.0, 1.0, 0.0, 6500.0}, {3.0, 0.5, 20.0, 3250.0}};
  EXPECT_DOUBLE_EQ(illumination_at(keys, 0.0).scale, 1.0);
  EXPECT_DOUBLE_EQ(illumination_at(keys, 9.0).shift, 20.0);
  const Illumination mid = illumination_at(keys, 2.0);
  EXPECT_DOUBLE_EQ(mid.scale, 0.75);
  EXPECT_DOUBLE_EQ(mid.shift, 10.0);
  // Halfway in mireds: 1e6 / ((1e6/6500 + 1e6/3250) / 2) = 4333.3 K, not 4875 K.
  EXPECT_NEAR(mid.temperature, 4333.333333, 1e-6);
  EXPECT_DOUBLE_EQ(illumination_at({}, 5.0).scale, 1.0);
}

TEST(Lighting, AppliesTheDiagonalModel) {
  cv::Mat colour(2, 2, CV_32FC3, cv::Scalar(100, 100, 100));
  const Illumination light{0.5, 10.0, 3800.0};
  apply_illumination(colour, light);
  const cv::Vec3d g = black_body_gains_bgr(3800.0);
  const cv::Vec3f p = colour.at<cv::Vec3f>(1, 1);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], 0.5 * g[k] * 100.0 + 10.0, 1e-3);
}

}  // namespace
}  // namespace facadeslam::synth
