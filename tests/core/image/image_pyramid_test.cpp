#include "core/image/image_pyramid.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "tests/support/random_rectangles.hpp"

namespace facadeslam {
namespace {

cv::Mat textured(cv::Size size) {
  cv::Mat img(size, CV_8UC3);
  cv::RNG rng(7);
  img.setTo(cv::Scalar(120, 120, 120));
  test::paint_random_rectangles(img, rng, 300, 0, 6, 30);
  return img;
}

TEST(ImagePyramid, FourHalvedGreyLevelsEachWithCorners) {
  const ImagePyramid pyramid(textured({640, 480}));
  ASSERT_EQ(pyramid.levels(), 4);
  const cv::Size expected[] = {{640, 480}, {320, 240}, {160, 120}, {80, 60}};
  for (int l = 0; l < 4; ++l) {
    EXPECT_EQ(pyramid.level(l).image.size(), expected[l]);
    EXPECT_EQ(pyramid.level(l).image.type(), CV_8UC1);
    EXPECT_FALSE(pyramid.level(l).corners.empty()) << "level " << l;
  }
  EXPECT_GT(pyramid.level(0).corners.size(), pyramid.level(3).corners.size());
}

TEST(ImagePyramid, CoordinateConventionMatchesHalfSampling) {
  // A bright 8x8 block at level 0 becomes a 1x1 pixel at level 3; the block's
  // centre must map onto that pixel's centre.
  cv::Mat img(256, 256, CV_8UC1, cv::Scalar(0));
  const int x0 = 64, y0 = 96;  // multiples of 8 so the block is one level-3 pixel
  img(cv::Rect(x0, y0, 8, 8)).setTo(255);
  const ImagePyramid pyramid(img, {.fast = {}, .detect_corners = false});
  const Eigen::Vector2d centre0(x0 + 3.5, y0 + 3.5);
  const Eigen::Vector2d centre3 = ImagePyramid::level0_to_level(centre0, 3);
  EXPECT_DOUBLE_EQ(centre3.x(), x0 / 8);
  EXPECT_DOUBLE_EQ(centre3.y(), y0 / 8);
  EXPECT_EQ(pyramid.level(3).image.at<std::uint8_t>(static_cast<int>(centre3.y()), static_cast<int>(centre3.x())), 255);
  const Eigen::Vector2d back = ImagePyramid::level_to_level0(centre3, 3);
  EXPECT_NEAR((back - centre0).norm(), 0.0, 1e-12);
}

TEST(ImagePyramid, RejectsImagesTooSmallForFourLevels) {
  try {
    ImagePyramid pyramid(cv::Mat(40, 200, CV_8UC1, cv::Scalar(0)));
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("at least 64"), std::string::npos) << e.what();
  }
}

TEST(ImagePyramid, RejectsUnsupportedImageTypes) {
  EXPECT_THROW(ImagePyramid(cv::Mat(128, 128, CV_32FC1, cv::Scalar(0))), Error);
}

}  // namespace
}  // namespace facadeslam
