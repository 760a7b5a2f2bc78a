#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "sequences/synth/procedural_textures.hpp"

namespace facadeslam::synth {
namespace {

GroundArea area(double x0, int columns, int rows) {
  GroundArea a;
  a.x0 = x0;
  a.y1 = 4.0;
  a.columns = columns;
  a.rows = rows;
  a.texel = 0.02;
  a.texel_y = 0.02;
  return a;
}

TEST(ProceduralTextures, NoiseIsBoundedAndSeeded) {
  for (int i = 0; i < 1000; ++i) {
    const double v = fractal_noise(i * 0.37, i * 0.11, 4, 7);
    ASSERT_GE(v, 0.0);
    ASSERT_LE(v, 1.0);
  }
  EXPECT_EQ(value_noise(1.3, 2.7, 5), value_noise(1.3, 2.7, 5));
  EXPECT_NE(value_noise(1.3, 2.7, 5), value_noise(1.3, 2.7, 6));
}

TEST(ProceduralTextures, TilesOfOneSurfaceJoinExactly) {
  // A road texture made in one piece equals the same road made as two tiles
  // (the renderer tiles long streets), texel for texel.
  const StreetSpec street;
  const cv::Mat whole = road_texture(area(3.0, 256, 64), street, 11);
  const cv::Mat left = road_texture(area(3.0, 128, 64), street, 11);
  const cv::Mat right = road_texture(area(3.0 + 128 * 0.02, 128, 64), street, 11);
  cv::Mat joined;
  cv::hconcat(left, right, joined);
  EXPECT_EQ(cv::norm(whole, joined, cv::NORM_INF), 0.0);
  const cv::Mat pave_whole = pavement_texture(area(3.0, 256, 64), street, 1, 11);
  cv::Mat pave_joined;
  cv::hconcat(pavement_texture(area(3.0, 128, 64), street, 1, 11),
              pavement_texture(area(3.0 + 128 * 0.02, 128, 64), street, 1, 11), pave_joined);
  EXPECT_EQ(cv::norm(pave_whole, pave_joined, cv::NORM_INF), 0.0);
}

// Repetition would let the tracker match the wrong copy of a patch: a patch
// of the texture must not reappear anywhere else along the street.
double best_match_elsewhere(const cv::Mat& texture, cv::Rect patch) {
  cv::Mat grey, scores;
  cv::cvtColor(texture, grey, cv::COLOR_BGR2GRAY);
  cv::matchTemplate(grey, grey(patch), scores, cv::TM_CCOEFF_NORMED);
  // Blank out the patch's own neighbourhood.
  cv::rectangle(scores, cv::Rect(patch.x - patch.width, patch.y - patch.height, 2 * patch.width, 2 * patch.height),
                cv::Scalar(-1), cv::FILLED);
  double best = 0.0;
  cv::minMaxLoc(scores, nullptr, &best);
  return best;
}

TEST(ProceduralTextures, GroundTexturesDoNotRepeat) {
  const StreetSpec street;
  const cv::Mat road = road_texture(area(0.0, 2000, 150), street, 3);
  const cv::Mat pavement = pavement_texture(area(0.0, 2000, 150), street, 1, 3);
  for (int x : {200, 900, 1600}) {
    EXPECT_LT(best_match_elsewhere(road, cv::Rect(x, 60, 40, 40)), 0.6) << "road at " << x;
    EXPECT_LT(best_match_elsewhere(pavement, cv::Rect(x, 60, 40, 40)), 0.6) << "pavement at " << x;
  }
}

TEST(ProceduralTextures, GroundIsTexturedEnoughForCorners) {
  // Mid-scale contrast: the standard deviation after removing the mean.
  const cv::Mat road = road_texture(area(0.0, 400, 200), StreetSpec{}, 3);
  cv::Mat grey;
  cv::cvtColor(road, grey, cv::COLOR_BGR2GRAY);
  cv::Scalar mean, sigma;
  cv::meanStdDev(grey, mean, sigma);
  EXPECT_GT(sigma[0], 5.0);
}

TEST(ProceduralTextures, SkyIsBrighterAtTheHorizonAndSeamless) {
  SkySpec sky;
  sky.clouds = 0.0;
  const cv::Mat panorama = sky_panorama(256, 128, sky, 1);
  const cv::Vec3b zenith = panorama.at<cv::Vec3b>(0, 10), horizon = panorama.at<cv::Vec3b>(63, 10);
  EXPECT_LT(zenith[1], horizon[1]);
  // Clouds on: the first and last columns (azimuth -180 and +180) match.
  sky.clouds = 0.6;
  const cv::Mat cloudy = sky_panorama(256, 128, sky, 1);
  EXPECT_LT(cv::norm(cloudy.col(0), cloudy.col(255), cv::NORM_INF), 12.0);
  EXPECT_GT(cv::norm(cloudy, panorama, cv::NORM_INF), 30.0);  // there are clouds
}

}  // namespace
}  // namespace facadeslam::synth
