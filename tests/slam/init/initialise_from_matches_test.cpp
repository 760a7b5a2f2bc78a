// The geometric core on synthetic matches (no images, no KLT): model choice,
// pose and structure accuracy, and the refusals.
#include "slam/init/initialise_from_matches.hpp"

#include <cstdio>
#include <functional>
#include <limits>

#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "tests/slam/init/synthetic_two_view.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using test::error_of;

using test::kDeg;
using test::SceneShape;

// Sideways camera motion of 0.3 m with a small rotation (turning slightly
// toward the scene), the motion a user makes when starting PTAM.
SE3d sideways_motion() { return test::second_camera({0.3, 0.02, 0.0}, {0.3 * kDeg, -2.0 * kDeg, 0.5 * kDeg}); }

struct Accuracy {
  double rotation_deg = 0.0;
  double direction_deg = 0.0;
  double point_median = 0.0;  // relative 3D error after fixing the scale from |t|
  double point_p90 = 0.0;
  int outliers_kept = 0;
};

Accuracy measure(const TwoViewResult& r, const SE3d& truth, const test::SyntheticMatches& m) {
  Accuracy a;
  a.rotation_deg = test::rotation_error_deg(r.T_c1_c0, truth);
  a.direction_deg = test::direction_error_deg(r.T_c1_c0.translation(), truth.translation());
  const double scale = truth.translation().norm() / r.T_c1_c0.translation().norm();
  std::vector<double> errors;
  for (std::size_t k = 0; k < r.points_c0.size(); ++k) {
    const auto i = static_cast<std::size_t>(r.match_indices[k]);
    if (m.outlier[i]) {
      ++a.outliers_kept;
      continue;
    }
    errors.push_back((r.points_c0[k] * scale - m.points_c0[i]).norm() / m.points_c0[i].norm());
  }
  a.point_median = test::percentile(errors, 0.5);
  a.point_p90 = test::percentile(errors, 0.9);
  return a;
}

void print(const char* what, const std::string& camera, const TwoViewResult& r, const Accuracy& a) {
  std::printf(
      "[ measured ] %s/%s: model %s R_H %.3f inliers H %d E %d, %zu points, median parallax %.2f deg, "
      "rotation error %.4f deg, direction error %.3f deg, point error median %.3f%% p90 %.3f%%, "
      "outliers kept %d\n",
      what, camera.c_str(), to_string(r.model), r.homography_ratio, r.inliers_homography, r.inliers_essential,
      r.points_c0.size(), r.median_parallax_deg, a.rotation_deg, a.direction_deg, 100.0 * a.point_median,
      100.0 * a.point_p90, a.outliers_kept);
}

class InitialiseFromMatchesCameras : public ::testing::TestWithParam<std::string> {};

// Bounds. Every match carries 0.3 px of Gaussian noise on both pixels (a
// pessimistic KLT figure: the rendered-plane test measures 0.04 px median).
// They were set from a sweep of 30 seeds x 3 cameras per scene, worst case
// in brackets, not from the one seed each test uses:
//  * rotation: 3D scene [0.08 deg], facade [0.08], with 30% outliers [0.11];
//  * translation direction: 3D scene [0.33 deg], with outliers [0.80],
//    facade [1.1]. A plane couples rotation and translation (bas-relief): a
//    rotation error dw appears as a direction error of about dw * d / |t|,
//    here x13, hence the wider facade bound;
//  * points, relative 3D error once the scale is fixed from |t|: 0.3 px moves
//    a 6 m point's depth by ~2% under a 0.3 m baseline, and a direction error
//    shifts them all together, so the median [2.4%] and the 90th percentile
//    [5.1%] are bounded, not every point.
constexpr double kRotationBoundDeg = 0.1;
constexpr double kOutlierRotationBoundDeg = 0.15;
constexpr double kDirectionBoundDeg = 1.0;
constexpr double kFacadeDirectionBoundDeg = 1.5;
constexpr double kPointMedianBound = 0.025;
constexpr double kPointP90Bound = 0.06;

// (a) A general 3D scene: the essential matrix must win and give the pose up
// to scale.
TEST_P(InitialiseFromMatchesCameras, GeneralSceneChoosesTheEssentialMatrix) {
  const Camera camera = test::camera_by_name(GetParam());
  const SE3d truth = sideways_motion();
  const auto m = test::make_matches(camera, truth, SceneShape::box, 400, 0.3, 0.0, 11);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  ASSERT_EQ(r.status, InitStatus::success) << r.reason;
  const Accuracy a = measure(r, truth, m);
  print("general scene", GetParam(), r, a);
  EXPECT_EQ(r.model, TwoViewModel::essential);
  EXPECT_LT(r.homography_ratio, 0.45);
  EXPECT_LT(a.rotation_deg, kRotationBoundDeg);
  EXPECT_LT(a.direction_deg, kDirectionBoundDeg);
  EXPECT_LT(a.point_median, kPointMedianBound);
  EXPECT_LT(a.point_p90, kPointP90Bound);
  EXPECT_GT(r.points_c0.size(), 0.9 * m.points_c0.size());
}

// (b) A facade plane: the homography must win (R_H > 0.45) and its
// decomposition give the same accuracy; the points lie on one plane.
TEST_P(InitialiseFromMatchesCameras, FacadePlaneChoosesTheHomography) {
  const Camera camera = test::camera_by_name(GetParam());
  const SE3d truth = sideways_motion();
  const auto m = test::make_matches(camera, truth, SceneShape::plane, 400, 0.3, 0.0, 12);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  ASSERT_EQ(r.status, InitStatus::success) << r.reason;
  const Accuracy a = measure(r, truth, m);
  print("facade plane", GetParam(), r, a);
  EXPECT_EQ(r.model, TwoViewModel::homography);
  EXPECT_GT(r.homography_ratio, 0.45);
  EXPECT_LT(a.rotation_deg, kRotationBoundDeg);
  EXPECT_LT(a.direction_deg, kFacadeDirectionBoundDeg);
  EXPECT_LT(a.point_median, kPointMedianBound);
  EXPECT_LT(a.point_p90, kPointP90Bound);
  EXPECT_GT(r.points_c0.size(), 0.9 * m.points_c0.size());
}

// (e) 30% of the matches are random: RANSAC and the reprojection checks must
// still give the same pose, and (almost) no outlier may become a map point
// (a random match can fall within 2 px of its epipolar line by chance).
TEST_P(InitialiseFromMatchesCameras, ThirtyPercentOutliersStillSucceed) {
  const Camera camera = test::camera_by_name(GetParam());
  const SE3d truth = sideways_motion();
  const auto m = test::make_matches(camera, truth, SceneShape::box, 400, 0.3, 0.3, 13);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  ASSERT_EQ(r.status, InitStatus::success) << r.reason;
  const Accuracy a = measure(r, truth, m);
  print("30% outliers", GetParam(), r, a);
  EXPECT_EQ(r.model, TwoViewModel::essential);
  EXPECT_LT(a.rotation_deg, kOutlierRotationBoundDeg);
  EXPECT_LT(a.direction_deg, kDirectionBoundDeg);
  EXPECT_LT(a.point_median, kPointMedianBound);
  EXPECT_LE(a.outliers_kept, static_cast<int>(0.02 * r.points_c0.size()));
}

// (c) Pure rotation: lots of image motion, no parallax at all.
TEST_P(InitialiseFromMatchesCameras, PureRotationIsDegenerate) {
  const Camera camera = test::camera_by_name(GetParam());
  const SE3d truth = test::second_camera(Eigen::Vector3d::Zero(), {2.0 * kDeg, -5.0 * kDeg, 1.0 * kDeg});
  const auto m = test::make_matches(camera, truth, SceneShape::box, 400, 0.3, 0.0, 14);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  EXPECT_EQ(r.status, InitStatus::degenerate);
  EXPECT_NE(r.reason.find("pure rotation"), std::string::npos) << r.reason;
  EXPECT_GT(r.median_image_motion_px, 30.0);
  EXPECT_TRUE(r.points_c0.empty());
}

// A facade seen square-on while the camera slides parallel to it: the case
// where the homography's two decompositions are closest. The wrong one puts
// about half the points behind a camera, so the choice is not ambiguous.
TEST(InitialiseFromMatches, FrontoParallelFacadeIsNotAmbiguous) {
  const Camera camera = test::plain_camera();
  const SE3d truth = test::second_camera({0.3, 0.0, 0.0}, Eigen::Vector3d::Zero());
  const auto m = test::make_matches(camera, truth, SceneShape::plane, 400, 0.3, 0.0, 22, 0.0);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  ASSERT_EQ(r.status, InitStatus::success) << r.reason;
  const Accuracy a = measure(r, truth, m);
  print("fronto-parallel facade", "plain", r, a);
  EXPECT_EQ(r.model, TwoViewModel::homography);
  EXPECT_LT(a.rotation_deg, kRotationBoundDeg);
  EXPECT_LT(a.direction_deg, kFacadeDirectionBoundDeg);
  EXPECT_LT(a.point_median, kPointMedianBound);
}

// Outliers hurt both scores alike, so a facade still picks the homography.
TEST(InitialiseFromMatches, FacadeWithThirtyPercentOutliersStillChoosesTheHomography) {
  const Camera camera = test::opencv_left_camera();
  const SE3d truth = sideways_motion();
  const auto m = test::make_matches(camera, truth, SceneShape::plane, 400, 0.3, 0.3, 23);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  ASSERT_EQ(r.status, InitStatus::success) << r.reason;
  const Accuracy a = measure(r, truth, m);
  print("facade, 30% outliers", "opencv_left", r, a);
  EXPECT_EQ(r.model, TwoViewModel::homography);
  EXPECT_LT(a.rotation_deg, kOutlierRotationBoundDeg);
  EXPECT_LT(a.direction_deg, kFacadeDirectionBoundDeg);
  EXPECT_LT(a.point_median, kPointMedianBound);
  EXPECT_LE(a.outliers_kept, static_cast<int>(0.02 * r.points_c0.size()));
}

INSTANTIATE_TEST_SUITE_P(Cameras, InitialiseFromMatchesCameras, ::testing::Values("plain", "opencv_left", "atan"));

// (d) A tiny translation (1 cm at 2-6 m, ~1 px of motion): nothing is tried.
TEST(InitialiseFromMatches, TinyTranslationNeedsMoreParallax) {
  const Camera camera = test::plain_camera();
  const SE3d truth = test::second_camera({0.01, 0.0, 0.0}, Eigen::Vector3d::Zero());
  const auto m = test::make_matches(camera, truth, SceneShape::box, 400, 0.3, 0.0, 15);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  EXPECT_EQ(r.status, InitStatus::need_more_parallax) << r.reason;
  EXPECT_LT(r.median_image_motion_px, 12.0);
  EXPECT_NE(r.reason.find("median image motion"), std::string::npos) << r.reason;
}

// (d') The same tiny translation hidden under a rotation: the image moves
// enough to try, but the parallax is far below 1 degree, so the attempt is
// refused as degenerate (the caller keeps feeding frames either way).
TEST(InitialiseFromMatches, TinyTranslationUnderRotationIsDegenerate) {
  const Camera camera = test::plain_camera();
  const SE3d truth = test::second_camera({0.01, 0.0, 0.0}, {0.0, -4.0 * kDeg, 0.0});
  const auto m = test::make_matches(camera, truth, SceneShape::box, 400, 0.3, 0.0, 16);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  EXPECT_EQ(r.status, InitStatus::degenerate) << r.reason;
  EXPECT_GT(r.median_image_motion_px, 12.0);
}

// Not enough parallax ANGLE although the translation is real: 4 cm at
// 2-6 m gives a median parallax well under the 1 degree required.
TEST(InitialiseFromMatches, SmallParallaxAngleIsDegenerate) {
  const Camera camera = test::plain_camera();
  const SE3d truth = test::second_camera({0.04, 0.0, 0.0}, {0.0, -3.0 * kDeg, 0.0});
  const auto m = test::make_matches(camera, truth, SceneShape::box, 400, 0.3, 0.0, 17);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  EXPECT_EQ(r.status, InitStatus::degenerate) << r.reason;
  EXPECT_LT(r.median_parallax_deg, 1.0);
}

TEST(InitialiseFromMatches, ScaleIsMedianDepthOneAndPixelsAreTheInputPairs) {
  const Camera camera = test::opencv_left_camera();
  const SE3d truth = sideways_motion();
  const auto m = test::make_matches(camera, truth, SceneShape::box, 300, 0.3, 0.0, 18);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  ASSERT_EQ(r.status, InitStatus::success) << r.reason;
  ASSERT_EQ(r.points_c0.size(), r.pixels0.size());
  ASSERT_EQ(r.points_c0.size(), r.pixels1.size());
  ASSERT_EQ(r.points_c0.size(), r.match_indices.size());
  std::vector<double> depths;
  for (const Eigen::Vector3d& p : r.points_c0) depths.push_back(p.z());
  std::nth_element(depths.begin(), depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2), depths.end());
  EXPECT_NEAR(depths[depths.size() / 2], 1.0, 1e-12);
  // Scale agrees with the truth: |t| / median depth.
  std::vector<double> true_depths;
  for (const Eigen::Vector3d& p : m.points_c0) true_depths.push_back(p.z());
  const double true_ratio = truth.translation().norm() / test::percentile(true_depths, 0.5);
  EXPECT_NEAR(r.T_c1_c0.translation().norm(), true_ratio, 0.05 * true_ratio);
  for (std::size_t k = 0; k < r.points_c0.size(); ++k) {
    const auto i = static_cast<std::size_t>(r.match_indices[k]);
    EXPECT_EQ(r.pixels0[k], m.pixels0[i]);
    EXPECT_EQ(r.pixels1[k], m.pixels1[i]);
    // Each point reprojects onto its pixels in both views.
    EXPECT_LT((camera.project(r.points_c0[k]) - r.pixels0[k]).norm(), 2.0);
    EXPECT_LT((camera.project(r.T_c1_c0 * r.points_c0[k]) - r.pixels1[k]).norm(), 2.0);
    if (k > 0) {
      EXPECT_LT(r.match_indices[k - 1], r.match_indices[k]);
    }
  }
}

// The map maker's --sync mode needs bit-identical results for the same input.
TEST(InitialiseFromMatches, IsDeterministic) {
  const Camera camera = test::plain_camera();
  const auto m = test::make_matches(camera, sideways_motion(), SceneShape::box, 300, 0.3, 0.3, 19);
  const TwoViewResult a = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  const TwoViewResult b = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  ASSERT_EQ(a.status, InitStatus::success) << a.reason;
  EXPECT_EQ(a.T_c1_c0.matrix(), b.T_c1_c0.matrix());
  EXPECT_EQ(a.match_indices, b.match_indices);
  EXPECT_EQ(a.points_c0, b.points_c0);
}

TEST(InitialiseFromMatches, TooFewMatchesAsksForARestart) {
  const Camera camera = test::plain_camera();
  const auto m = test::make_matches(camera, sideways_motion(), SceneShape::box, 60, 0.3, 0.0, 20);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  EXPECT_EQ(r.status, InitStatus::too_few_tracks);
  EXPECT_EQ(r.matches, 60);
  const TwoViewResult none = initialise_from_matches(camera, {}, {}, TwoViewOptions{});
  EXPECT_EQ(none.status, InitStatus::too_few_tracks);
}

// All matches random: no model explains them.
TEST(InitialiseFromMatches, RandomMatchesAreRefused) {
  const Camera camera = test::plain_camera();
  const auto m = test::make_matches(camera, sideways_motion(), SceneShape::box, 300, 0.3, 1.0, 21);
  const TwoViewResult r = initialise_from_matches(camera, m.pixels0, m.pixels1, TwoViewOptions{});
  EXPECT_EQ(r.status, InitStatus::degenerate) << r.reason;
  EXPECT_TRUE(r.points_c0.empty());
}

TEST(InitialiseFromMatches, MismatchedListsThrow) {
  const Camera camera = test::plain_camera();
  const std::vector<Eigen::Vector2d> two(2, Eigen::Vector2d(1, 1)), three(3, Eigen::Vector2d(1, 1));
  EXPECT_NE(
      error_of([&] { initialise_from_matches(camera, two, three, TwoViewOptions{}); }).find("2 reference pixels but 3"),
      std::string::npos);
}

TEST(InitialiseFromMatches, NonFinitePixelThrows) {
  const Camera camera = test::plain_camera();
  std::vector<Eigen::Vector2d> a(3, Eigen::Vector2d(1, 1)), b = a;
  b[2].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_of([&] { initialise_from_matches(camera, a, b, TwoViewOptions{}); }).find("match 2 has a non-finite"),
            std::string::npos);
}

TEST(InitialiseFromMatches, OptionOutOfRangeThrows) {
  const Camera camera = test::plain_camera();
  TwoViewOptions options;
  options.match_sigma_px = 0.0;
  EXPECT_NE(error_of([&] { initialise_from_matches(camera, {}, {}, options); }).find("match_sigma_px"),
            std::string::npos);
}

}  // namespace
}  // namespace facadeslam
