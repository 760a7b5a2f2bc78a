// StripSums: the column sums a row's keypoints share must give the patch
// definitions (patch_mean_std, gradient_region_means, compute_patch_moments)
// and must not depend on which other keypoints share the row.
#include <gtest/gtest.h>

#include <vector>

#include "semantics/descriptor/modules/gradient_angles_module.hpp"
#include "semantics/descriptor/modules/mean_std.hpp"
#include "semantics/descriptor/modules/patch_moments.hpp"
#include "semantics/descriptor/modules/strip_sums.hpp"
#include "tests/semantics/semantics_test_util.hpp"

namespace facadeslam::semantics {
namespace {

// A plane with structure and a large offset (like distances), radius 4.
cv::Mat test_plane() {
  cv::Mat plane(40, 57, CV_32F);
  for (int y = 0; y < plane.rows; ++y)
    for (int x = 0; x < plane.cols; ++x)
      plane.at<float>(y, x) =
          300.0f + 20.0f * std::sin(0.37f * x) * std::cos(0.23f * y) + 0.01f * static_cast<float>(x * y);
  return plane;
}

PlaneSet only(PlaneId p) {
  PlaneSet s;
  s.set(plane_bit(p));
  return s;
}

TEST(StripSums, MeanAndSigmaMatchThePatchDefinition) {
  const int r = 4;
  const PreparedImage image = test_util::image_with_plane(PlaneId::edge_distance, test_plane(), r);
  StripSums strip;
  strip.configure(image, r, only(PlaneId::edge_distance), {});
  for (const int y : {0, 3, 17, 39}) {
    std::vector<int> centres;
    for (int x = 0; x < image.image_size.width; x += 5) centres.push_back(x);
    centres.push_back(image.image_size.width - 1);
    strip.compute(y, centres);
    for (const int x : centres) {
      const MeanStd expected = patch_mean_std(image.patch(PlaneId::edge_distance, x, y, r));
      const MeanStd got = strip.mean_std(PlaneId::edge_distance, x);
      // Both sum float deviations, from different centres: agreement to the
      // float precision of the values.
      EXPECT_NEAR(got.mean, expected.mean, 1e-7 * expected.mean) << x << "," << y;
      EXPECT_NEAR(got.std, expected.std, 1e-5 * expected.std) << x << "," << y;
    }
  }
}

TEST(StripSums, RegionMeansEqualThePatchDefinition) {
  const int r = 3;
  const PreparedImage image = test_util::image_with_plane(PlaneId::angle1, test_plane(), r);
  StripSums strip;
  strip.configure(image, r, {}, only(PlaneId::angle1));
  const std::vector<int> centres{0, 1, 2, 9, 30, 56};
  strip.compute(11, centres);
  for (const int x : centres)
    EXPECT_EQ(strip.region_means(PlaneId::angle1, x), gradient_region_means(image.patch(PlaneId::angle1, x, 11, r)))
        << x;
}

TEST(StripSums, ValuesDoNotDependOnTheOtherKeypointsOfTheRow) {
  const int r = 4;
  const PreparedImage image = test_util::image_with_plane(PlaneId::gevers_c2, test_plane(), r);
  StripSums strip;
  strip.configure(image, r, only(PlaneId::gevers_c2), {});
  strip.compute(20, {25});
  const MeanStd alone = strip.mean_std(PlaneId::gevers_c2, 25);
  strip.compute(20, {3, 11, 19, 25, 26, 50});
  const MeanStd shared = strip.mean_std(PlaneId::gevers_c2, 25);
  EXPECT_EQ(alone.mean, shared.mean);
  EXPECT_EQ(alone.std, shared.std);
}

void expect_same_moments(const PatchMoments& got, const PatchMoments& expected, int order, int x) {
  EXPECT_EQ(got.order, expected.order);
  for (int p = 0; p <= order; ++p)
    for (int q = 0; p + q <= order; ++q) EXPECT_EQ(got.mu[p][q], expected.mu[p][q]) << "mu" << p << q << " at x=" << x;
  for (int k = 0; k <= kMaxMomentOrder; ++k) EXPECT_EQ(got.eta_scale[k], expected.eta_scale[k]) << k;
  for (int k = 0; k < 15; ++k) EXPECT_EQ(got.mass_powers[k], expected.mass_powers[k]) << k;
}

TEST(StripSums, MomentsAreThePatchMomentsBitForBit) {
  // Every order and two radii, at the image edges (reflected border) and
  // inside, on a row shared by many keypoints and by one alone.
  for (const int r : {3, 10}) {
    const PreparedImage image = test_util::image_with_plane(PlaneId::colour1, test_plane(), r);
    for (int order = 0; order <= kMaxMomentOrder; ++order) {
      StripSums strip;
      strip.configure(image, r, {}, {}, {-1, order, -1});
      ASSERT_TRUE(strip.has_moments(1) && !strip.has_moments(0));
      const std::vector<int> centres{0, 1, 8, 9, 30, 55, 56};
      for (const int y : {0, 19, 39}) {
        strip.compute(y, centres);
        for (const int x : centres) {
          PatchMoments got, expected;
          strip.moments(1, x, got);
          compute_patch_moments(image.patch(PlaneId::colour1, x, y, r), order, expected);
          expect_same_moments(got, expected, order, x);
        }
        PatchMoments shared, alone;
        strip.moments(1, 30, shared);
        strip.compute(y, {30});
        strip.moments(1, 30, alone);
        expect_same_moments(alone, shared, order, 30);
      }
    }
  }
}

}  // namespace
}  // namespace facadeslam::semantics
