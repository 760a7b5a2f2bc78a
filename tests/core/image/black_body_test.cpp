#include "core/image/black_body.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

TEST(BlackBody, ReferenceIsNeutralAndGreenKeepsItsValue) {
  const cv::Vec3d g = black_body_gains_bgr(kReferenceIlluminantKelvin);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(g[c], 1.0, 1e-12);
  for (const double k : {2000.0, 3800.0, 10000.0}) EXPECT_DOUBLE_EQ(black_body_gains_bgr(k)[1], 1.0);
}

TEST(BlackBody, WarmLightIsRedderColdLightBluerAndBothChangeSteadily) {
  const cv::Vec3d warm = black_body_gains_bgr(3800.0), cold = black_body_gains_bgr(10000.0);
  // The values the documentation gives (B, G, R order).
  EXPECT_NEAR(warm[2], 1.33, 0.01);
  EXPECT_NEAR(warm[0], 0.60, 0.01);
  EXPECT_LT(cold[2], 1.0);
  EXPECT_GT(cold[0], 1.0);
  double red = 10.0, blue = 0.0;
  for (double k = 1000.0; k <= 40000.0; k *= 1.25) {
    const cv::Vec3d g = black_body_gains_bgr(k);
    EXPECT_LT(g[2], red) << k;
    EXPECT_GT(g[0], blue) << k;
    red = g[2];
    blue = g[0];
  }
}

TEST(BlackBody, RejectsTemperaturesOutsideTheModel) {
  EXPECT_THAT(test::error_of([] { black_body_gains_bgr(100.0); }), ::testing::HasSubstr("500 and 100000 K"));
  EXPECT_THAT(test::error_of([] { black_body_gains_bgr(std::nan("")); }), ::testing::HasSubstr("500 and 100000 K"));
}

}  // namespace
}  // namespace facadeslam
