// StripSums: the column sums a row's keypoints share must give the patch
// definitions (patch_mean_std, gradient_region_means) and must not depend on
// which other keypoints share the row.
#include <gtest/gtest.h>

#include <vector>

#include "semantics/descriptor/modules/gradient_angles_module.hpp"
#include "semantics/descriptor/modules/mean_std.hpp"
#include "semantics/descriptor/modules/strip_sums.hpp"
#include "tests/semantics/semantics_test_util.hpp"

namespace facadeslam::semantics {
namespace {

// A plane with structure and a large offset (like distances), radius 4.
cv::Mat test_plane() {
  cv::Mat plane(40, 57, CV_32F);
  for (int y = 0; y < plane.rows; ++y)
    for (int x = 0; x < plane.cols; ++x)
      plane.at<float>(y, x) = 300.0f + 20.0f * std::sin(0.37f * x) * std::cos(0.23f * y) + 0.01f * static_cast<float>(x * y);
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

}  // namespace
}  // namespace facadeslam::semantics
