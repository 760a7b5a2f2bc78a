#include "core/image/fast_detector.hpp"

#include <set>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

// Dark squares on a light background: each square has four FAST corners.
cv::Mat squares_image(cv::Size size, int step, cv::Rect region) {
  cv::Mat img(size, CV_8UC1, cv::Scalar(200));
  for (int y = region.y; y + step / 2 < region.y + region.height; y += step)
    for (int x = region.x; x + step / 2 < region.x + region.width; x += step)
      cv::rectangle(img, cv::Rect(x, y, step / 2, step / 2), cv::Scalar(40), cv::FILLED);
  return img;
}

TEST(FastDetector, FindsTheCornersOfASquare) {
  cv::Mat img(64, 64, CV_8UC1, cv::Scalar(200));
  cv::rectangle(img, cv::Rect(20, 24, 16, 12), cv::Scalar(30), cv::FILLED);
  const auto corners = detect_fast(img, {20, 32, 0, 4});
  const std::vector<cv::Point> expected{{20, 24}, {35, 24}, {20, 35}, {35, 35}};
  for (const auto& e : expected) {
    bool found = false;
    for (const auto& c : corners) found |= std::abs(c.x - e.x) <= 1 && std::abs(c.y - e.y) <= 1;
    EXPECT_TRUE(found) << "corner near (" << e.x << "," << e.y << ") not detected";
  }
  EXPECT_LE(corners.size(), 8u) << "non-maximum suppression should leave few corners per square corner";
}

TEST(FastDetector, OutputIsSortedByRowThenColumn) {
  const auto corners = detect_fast(squares_image({200, 150}, 16, {8, 8, 180, 130}), {20, 32, 0, 4});
  ASSERT_GT(corners.size(), 50u);
  for (std::size_t i = 1; i < corners.size(); ++i) {
    const auto& a = corners[i - 1];
    const auto& b = corners[i];
    EXPECT_TRUE(a.y < b.y || (a.y == b.y && a.x < b.x));
  }
}

TEST(FastDetector, BucketingCapsEachCellAndKeepsTheStrongest) {
  const cv::Mat img = squares_image({256, 256}, 8, {0, 0, 256, 256});
  const auto all = detect_fast(img, {20, 64, 0, 4});
  const auto kept = detect_fast(img, {20, 64, 5, 4});
  std::map<int, std::vector<float>> per_cell_all;
  for (const auto& c : all) per_cell_all[(c.y / 64) * 4 + c.x / 64].push_back(c.score);
  std::map<int, int> per_cell_kept;
  for (const auto& c : kept) {
    const int cell = (c.y / 64) * 4 + c.x / 64;
    ++per_cell_kept[cell];
    // Every kept corner is at least as strong as the 5th strongest of its cell.
    auto scores = per_cell_all[cell];
    std::sort(scores.rbegin(), scores.rend());
    EXPECT_GE(c.score, scores[std::min<std::size_t>(4, scores.size() - 1)]);
  }
  for (const auto& [cell, n] : per_cell_kept) EXPECT_LE(n, 5) << "cell " << cell;
  EXPECT_EQ(per_cell_kept.size(), 16u) << "every cell of the textured image keeps corners";
}

TEST(FastDetector, BucketingSpreadsCornersOverTheImage) {
  // A dense textured block in one corner and sparse squares elsewhere: without
  // bucketing, the dense block dominates a top-N selection.
  cv::Mat img = squares_image({320, 240}, 6, {0, 0, 100, 80});
  cv::Mat sparse = squares_image({320, 240}, 40, {120, 100, 200, 140});
  img.setTo(40, sparse < 100);
  const auto kept = detect_fast(img, {20, 40, 4, 4});
  std::size_t outside_dense = 0;
  for (const auto& c : kept) outside_dense += (c.x > 110 || c.y > 90);
  EXPECT_GT(outside_dense, kept.size() / 3) << "bucketing should keep the sparse region's corners";
}

TEST(FastDetector, BorderDropsCornersNearTheEdge) {
  const auto corners = detect_fast(squares_image({128, 128}, 8, {0, 0, 128, 128}), {20, 32, 0, 10});
  for (const auto& c : corners) {
    EXPECT_GE(c.x, 10);
    EXPECT_GE(c.y, 10);
    EXPECT_LT(c.x, 118);
    EXPECT_LT(c.y, 118);
  }
}

TEST(FastDetector, RejectsBadInput) {
  EXPECT_THROW(detect_fast(cv::Mat(32, 32, CV_8UC3), {}), Error);
  EXPECT_THROW(detect_fast(cv::Mat(32, 32, CV_8UC1), {0, 32, 1, 0}), Error);
}

}  // namespace
}  // namespace facadeslam
