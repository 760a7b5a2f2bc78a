// Brute-force matching and the match rate: the rule on hand-made distance
// matrices (ties and non-finite distances are misses), and the blocked
// computation against OpenCV's own brute-force matcher.
#include <cmath>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/features2d.hpp>

#include "core/util/error.hpp"
#include "semantics/invariance/match_rate.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

using ::testing::HasSubstr;

TEST(MatchedRows, CounterpartMustBeStrictlyNearest) {
  const cv::Mat d = (cv::Mat_<float>(4, 4) << 0.1f, 0.5f, 0.9f, 0.3f,  // own nearest: matched
                     0.2f, 0.3f, 0.1f, 0.9f,                           // two others nearer: miss
                     0.4f, 0.7f, 0.4f, 0.5f,                           // tie with another: miss
                     0.6f, 0.8f, 0.7f, 0.0f);                          // own at distance 0: matched
  EXPECT_EQ(matched_rows(d), (std::vector<bool>{true, false, false, true}));
}

TEST(MatchedRows, NonFiniteDistancesAreNeverNearest) {
  const float nan = std::nanf(""), inf = HUGE_VALF;
  const cv::Mat d = (cv::Mat_<float>(3, 3) << nan, 0.5f, 0.9f,  // own undefined: miss
                     nan, 0.3f, inf,                            // others undefined or infinite: matched
                     0.1f, 0.2f, inf);                          // own infinite: miss
  EXPECT_EQ(matched_rows(d), (std::vector<bool>{false, true, false}));
}

TEST(MatchedRows, NeedsASquareFloatMatrix) {
  EXPECT_THAT(test::error_of([] { matched_rows(cv::Mat(2, 3, CV_32F, cv::Scalar(0))); }), HasSubstr("square CV_32F"));
  EXPECT_THAT(test::error_of([] { matched_rows(cv::Mat(2, 2, CV_64F, cv::Scalar(0))); }), HasSubstr("square CV_32F"));
}

TEST(MatchRate, IsTheShareOfMatchedRows) {
  EXPECT_DOUBLE_EQ(match_rate(3, 4), 0.75);
  EXPECT_TRUE(std::isnan(match_rate(0, 0)));
}

// Random descriptors and a noisy copy of them: more rows than one block,
// and noise large enough that some keypoints are lost.
struct NoisyPair {
  cv::Mat reference, changed;
};

NoisyPair noisy_pair(int rows, int cols, double noise) {
  cv::RNG rng(7);
  NoisyPair p;
  p.reference.create(rows, cols, CV_32F);
  rng.fill(p.reference, cv::RNG::UNIFORM, 0.0, 1.0);
  cv::Mat jitter(rows, cols, CV_32F);
  rng.fill(jitter, cv::RNG::NORMAL, 0.0, noise);
  p.changed = p.reference + jitter;
  return p;
}

TEST(CountMatched, AgreesWithOpenCVsBruteForceMatcher) {
  const NoisyPair p = noisy_pair(700, 12, 0.3);
  std::vector<cv::DMatch> nearest;
  cv::BFMatcher(cv::NORM_L2).match(p.reference, p.changed, nearest);
  std::size_t expected = 0;
  for (const cv::DMatch& m : nearest) expected += m.queryIdx == m.trainIdx ? 1 : 0;
  const std::size_t matched = count_matched(p.reference, p.changed);
  EXPECT_EQ(matched, expected);  // random floats: no ties, so the rules agree
  EXPECT_GT(matched, 100u);      // the noise loses some keypoints, not all
  EXPECT_LT(matched, 650u);
}

TEST(CountMatched, IdenticalDescriptorsMatchUnlessTwoRowsAreEqual) {
  const NoisyPair p = noisy_pair(300, 8, 0.0);
  EXPECT_EQ(count_matched(p.reference, p.reference), 300u);
  cv::Mat twins = p.reference.clone();
  twins.row(5).copyTo(twins.row(260));  // two keypoints look the same: both are ambiguous
  EXPECT_EQ(count_matched(twins, twins), 298u);
  cv::Mat swapped = p.reference.clone();
  p.reference.row(3).copyTo(swapped.row(7));
  p.reference.row(7).copyTo(swapped.row(3));
  EXPECT_EQ(count_matched(p.reference, swapped), 298u);
}

TEST(CountMatched, MatricesMustAgreeInShapeAndType) {
  const cv::Mat a(4, 3, CV_32F, cv::Scalar(0)), b(5, 3, CV_32F, cv::Scalar(0)), c(4, 3, CV_64F, cv::Scalar(0));
  EXPECT_THAT(test::error_of([&] { count_matched(a, b); }), HasSubstr("same size"));
  EXPECT_THAT(test::error_of([&] { count_matched(a, c); }), HasSubstr("CV_32F"));
  EXPECT_EQ(count_matched(cv::Mat(0, 3, CV_32F), cv::Mat(0, 3, CV_32F)), 0u);
}

}  // namespace
}  // namespace facadeslam::semantics
