#include "core/patch/search_image.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"

namespace facadeslam::patch {
namespace {

cv::Mat squares() {
  cv::Mat image(240, 320, CV_8UC1, cv::Scalar(50));
  cv::RNG rng(2);
  for (int i = 0; i < 60; ++i) {
    // One draw a statement, in order: a call's arguments would be drawn in the compiler's order.
    const int x = rng.uniform(0, 300);
    const int y = rng.uniform(0, 220);
    const int width = rng.uniform(5, 30);
    const int height = rng.uniform(5, 30);
    const int brightness = rng.uniform(100, 250);
    cv::rectangle(image, cv::Rect(x, y, width, height), cv::Scalar(brightness), cv::FILLED);
  }
  return image;
}

TEST(SearchImage, RowsHoldExactlyTheCornersOfThatRow) {
  const ImagePyramid pyramid(squares());
  const SearchImage frame(pyramid);
  for (int l = 0; l < kPyramidLevels; ++l) {
    const auto& corners = pyramid.level(l).corners;
    std::size_t seen = 0;
    for (int y = 0; y < pyramid.level(l).image.rows; ++y) {
      const auto row = frame.row(l, y);
      for (const Corner& c : row) EXPECT_EQ(c.y, y);
      seen += row.size();
    }
    EXPECT_EQ(seen, corners.size()) << "level " << l;
    EXPECT_TRUE(frame.row(l, -1).empty());
    EXPECT_TRUE(frame.row(l, pyramid.level(l).image.rows).empty());
  }
  EXPECT_GT(pyramid.level(0).corners.size(), 20u);
}

TEST(SearchImage, RejectsCornersThatAreNotSorted) {
  std::array<PyramidLevel, kPyramidLevels> levels;
  for (int l = 0; l < kPyramidLevels; ++l)
    levels[static_cast<std::size_t>(l)].image = cv::Mat(64 >> l, 64 >> l, CV_8UC1);
  levels[0].corners = {{10, 20, 1.f}, {5, 12, 1.f}};  // row 20 before row 12
  const ImagePyramid unsorted(levels);
  EXPECT_THROW(SearchImage{unsorted}, Error);
  levels[0].corners = {{10, 20, 1.f}, {5, 20, 1.f}};  // columns out of order
  const ImagePyramid unsorted_columns(levels);
  EXPECT_THROW(SearchImage{unsorted_columns}, Error);
  levels[0].corners = {{10, 70, 1.f}};  // below the image
  const ImagePyramid outside(levels);
  EXPECT_THROW(SearchImage{outside}, Error);
}

}  // namespace
}  // namespace facadeslam::patch
