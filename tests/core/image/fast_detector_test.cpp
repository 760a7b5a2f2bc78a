#include "core/image/fast_detector.hpp"

#include <set>

#include <gtest/gtest.h>
#include <opencv2/features2d.hpp>
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

// FAST-9 by its definition, written for clarity: the score is the largest t
// for which 9 contiguous circle pixels are all brighter than centre + t or
// all darker than centre - t, plus the circle's summed absolute difference
// / 4096 to break ties; a corner is a candidate whose score beats its earlier
// raster neighbours and is not beaten by its later ones.
float reference_score(const cv::Mat& img, int x, int y) {
  static constexpr int kCircle[16][2] = {{0, -3}, {1, -3}, {2, -2}, {3, -1}, {3, 0},  {3, 1},   {2, 2},   {1, 3},
                                         {0, 3},  {-1, 3}, {-2, 2}, {-3, 1}, {-3, 0}, {-3, -1}, {-2, -2}, {-1, -3}};
  int d[16];
  unsigned sad = 0;
  for (int i = 0; i < 16; ++i) {
    d[i] = img.at<std::uint8_t>(y + kCircle[i][1], x + kCircle[i][0]) - img.at<std::uint8_t>(y, x);
    sad += static_cast<unsigned>(std::abs(d[i]));
  }
  int best = 0;
  for (int start = 0; start < 16; ++start) {
    int lo = 255, hi = -255;
    for (int j = 0; j < 9; ++j) {
      lo = std::min(lo, d[(start + j) % 16]);
      hi = std::max(hi, d[(start + j) % 16]);
    }
    best = std::max({best, lo, -hi});
  }
  return static_cast<float>(best) + static_cast<float>(sad) / 4096.f;
}

TEST(FastDetector, MatchesTheDefinitionCornerForCorner) {
  // Noise over squares: tens of thousands of candidates, score ties on the
  // squares' clean edges, a candidate count that is not a multiple of 8.
  cv::Mat img = squares_image({333, 251}, 12, {0, 0, 333, 251});
  cv::Mat noise(img.size(), CV_8UC1);
  cv::randu(noise, 0, 40);
  img.setTo(0, squares_image({333, 251}, 50, {20, 20, 300, 200}) < 100);
  img += noise;
  std::vector<cv::KeyPoint> candidates;
  cv::FAST(img, candidates, 10, false);
  ASSERT_GT(candidates.size(), 5000u);
  cv::Mat score(img.size(), CV_32FC1, cv::Scalar(0));
  for (const auto& kp : candidates)
    score.at<float>(static_cast<int>(kp.pt.y), static_cast<int>(kp.pt.x)) =
        reference_score(img, static_cast<int>(kp.pt.x), static_cast<int>(kp.pt.y));
  std::vector<Corner> expected;
  for (int y = 4; y < img.rows - 4; ++y)
    for (int x = 4; x < img.cols - 4; ++x) {
      const float s = score.at<float>(y, x);
      if (s == 0.f) continue;
      bool maximum = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const bool earlier = dy < 0 || (dy == 0 && dx < 0);
          const float n = score.at<float>(y + dy, x + dx);
          if ((dy != 0 || dx != 0) && (earlier ? n >= s : n > s)) maximum = false;
        }
      if (maximum) expected.push_back({x, y, s});
    }
  const auto corners = detect_fast(img, {10, 32, 0, 4});
  ASSERT_EQ(corners.size(), expected.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    EXPECT_EQ(corners[i].x, expected[i].x);
    EXPECT_EQ(corners[i].y, expected[i].y);
    EXPECT_EQ(corners[i].score, expected[i].score) << "at (" << corners[i].x << ", " << corners[i].y << ")";
  }
}

TEST(FastDetector, RejectsBadInput) {
  EXPECT_THROW(detect_fast(cv::Mat(32, 32, CV_8UC3), {}), Error);
  EXPECT_THROW(detect_fast(cv::Mat(32, 32, CV_8UC1), {0, 32, 1, 0}), Error);
}

}  // namespace
}  // namespace facadeslam
