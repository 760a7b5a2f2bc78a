// The building blocks of the initialiser: model scores, triangulation and
// the point checks, the relative-pose refinement, option validation.
#include <cmath>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "slam/init/essential_refinement.hpp"
#include "slam/init/homography_refinement.hpp"
#include "slam/init/init_options.hpp"
#include "slam/init/model_scoring.hpp"
#include "slam/init/two_view_triangulation.hpp"
#include "tests/slam/init/synthetic_two_view.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using test::error_of;

using test::kDeg;

// ---- model scores -------------------------------------------------------

TEST(ModelScoring, ExactHomographyScoresTheMaximumAndSpotsAnOutlier) {
  Eigen::Matrix3d H;
  H << 1.02, 0.01, 5.0, -0.02, 0.99, -3.0, 1e-5, 2e-5, 1.0;
  std::vector<Eigen::Vector2d> x0, x1;
  for (int i = 0; i < 20; ++i) {
    x0.emplace_back(30.0 * i, 15.0 * i + 7.0);
    x1.push_back((H * x0.back().homogeneous()).hnormalized());
  }
  x1[7] += Eigen::Vector2d(10.0, 0.0);  // 10 px off: chi-square 100 in both directions
  const ModelScore s = score_homography(H, x0, x1, 1.0);
  EXPECT_EQ(s.inlier_count, 19);
  EXPECT_FALSE(s.inliers[7]);
  EXPECT_TRUE(s.inliers[6]);
  EXPECT_NEAR(s.score, 19 * 2 * kChiSquare95TwoDof, 1e-6);
  // An error of 2 px at sigma 1: chi-square 4 < 5.991, inlier, scores 1.991 in that direction.
  const ModelScore s2 =
      score_homography(Eigen::Matrix3d::Identity(), {Eigen::Vector2d(0, 0)}, {Eigen::Vector2d(0, 2)}, 1.0);
  EXPECT_EQ(s2.inlier_count, 1);
  EXPECT_NEAR(s2.score, 2 * (kChiSquare95TwoDof - 4.0), 1e-9);
  // Sigma scales the test: the same 2 px at sigma 0.5 is chi-square 16.
  EXPECT_EQ(
      score_homography(Eigen::Matrix3d::Identity(), {Eigen::Vector2d(0, 0)}, {Eigen::Vector2d(0, 2)}, 0.5).inlier_count,
      0);
}

TEST(ModelScoring, SingularHomographyScoresZero) {
  Eigen::Matrix3d H = Eigen::Matrix3d::Identity();
  H(2, 2) = 0.0;
  H(1, 1) = 0.0;
  const ModelScore s = score_homography(H, {Eigen::Vector2d(1, 1)}, {Eigen::Vector2d(1, 1)}, 1.0);
  EXPECT_EQ(s.score, 0.0);
  EXPECT_EQ(s.inlier_count, 0);
}

TEST(ModelScoring, FundamentalMatrixUsesEpipolarDistances) {
  // Pure sideways motion: F = [e]x with epipolar lines horizontal, so a
  // vertical offset is the point-to-line distance and a horizontal one costs
  // nothing.
  const Eigen::Matrix3d F = SO3<double>::hat(Eigen::Vector3d::UnitX());
  const std::vector<Eigen::Vector2d> x0{{10, 20}, {50, 60}, {70, 80}};
  const std::vector<Eigen::Vector2d> x1{{40, 20}, {51, 61.5}, {90, 83}};
  const ModelScore s = score_fundamental(F, x0, x1, 1.0);
  EXPECT_TRUE(s.inliers[0]);
  EXPECT_TRUE(s.inliers[1]);   // 1.5 px: chi-square 2.25 < 3.841
  EXPECT_FALSE(s.inliers[2]);  // 3 px: chi-square 9
  EXPECT_NEAR(s.score, 2 * kChiSquare95TwoDof + 2 * (kChiSquare95TwoDof - 2.25), 1e-9);
}

// ---- triangulation -------------------------------------------------------

TEST(Triangulation, RecoversAnExactPointAndItsParallax) {
  const SE3d T = test::second_camera({0.5, 0.0, 0.0}, {0.0, -3.0 * kDeg, 0.0});
  const Eigen::Vector3d p(0.3, -0.2, 2.5);
  const Eigen::Vector3d p1 = T * p;
  const auto x = triangulate_dlt(T, p / p.z(), p1 / p1.z());
  ASSERT_TRUE(x.has_value());
  EXPECT_LT((*x - p).norm(), 1e-9);
  // Camera 1 centre at (1, 0, 0) and the point at (0, 0, 1): 45 degrees.
  const SE3d sideways(SO3<double>(), Eigen::Vector3d(-1.0, 0.0, 0.0));
  EXPECT_NEAR(parallax_angle(sideways, Eigen::Vector3d(0, 0, 1)), 45.0 * kDeg, 1e-12);
}

TEST(Triangulation, ParallelRaysGiveNoPoint) {
  const SE3d T(SO3<double>(), Eigen::Vector3d(-0.1, 0.0, 0.0));
  const Eigen::Vector3d ray(0.1, 0.2, 1.0);
  EXPECT_FALSE(triangulate_dlt(T, ray, ray).has_value());
}

TEST(Triangulation, EvaluatePoseSortsPointsByTheChecks) {
  const Camera camera = test::plain_camera();
  const SE3d T = test::second_camera({0.3, 0.0, 0.0}, Eigen::Vector3d::Zero());
  TwoViewMatches m;
  const auto add = [&](const Eigen::Vector3d& p, const Eigen::Vector2d& offset1) {
    m.pixels0.push_back(camera.project(p));
    m.pixels1.push_back(camera.project(T * p) + offset1);
    m.rays0.push_back(camera.unproject(m.pixels0.back()));
    m.rays1.push_back(camera.unproject(m.pixels1.back()));
  };
  add({0.1, 0.1, 3.0}, {0, 0});      // 0: good (5.7 deg)
  add({0.1, 0.1, 100.0}, {0, 0});    // 1: consistent, parallax 0.17 deg < 1 deg
  add({0.1, 0.1, 3.0}, {0, 8.0});    // 2: 8 px off the epipolar line: reprojection fails
  add({0.1, 0.1, 3.0}, {100.0, 0});  // 3: disparity reversed: behind the cameras
  PointCheckOptions options{2.0, 1.0 * kDeg};
  const PoseEvaluation e = evaluate_pose(camera, T, m, {0, 1, 2, 3}, options);
  EXPECT_EQ(e.consistent, (std::vector<int>{0, 1}));
  EXPECT_EQ(e.good, (std::vector<int>{0}));
  ASSERT_EQ(e.good_points_c0.size(), 1u);
  EXPECT_LT((e.good_points_c0[0] - Eigen::Vector3d(0.1, 0.1, 3.0)).norm(), 1e-6);
  EXPECT_NEAR(e.median_parallax_rad(), std::max(e.consistent_parallax_rad[0], e.consistent_parallax_rad[1]), 0.0);
  // The mirrored pose puts the good point behind both cameras.
  const PoseEvaluation mirrored = evaluate_pose(camera, T.inverse(), m, {0}, options);
  EXPECT_TRUE(mirrored.good.empty());
}

// ---- refinement ----------------------------------------------------------

TEST(EssentialRefinement, RemovesAPerturbationOfThePose) {
  const Camera camera = test::plain_camera();
  const SE3d truth = test::second_camera({0.3, 0.02, 0.0}, {0.3 * kDeg, -2.0 * kDeg, 0.5 * kDeg});
  const auto m = test::make_matches(camera, truth, test::SceneShape::box, 200, 0.0, 0.0, 5);
  std::vector<Eigen::Vector3d> rays0, rays1;
  std::vector<int> all;
  for (std::size_t i = 0; i < m.pixels0.size(); ++i) {
    rays0.push_back(camera.unproject(m.pixels0[i]));
    rays1.push_back(camera.unproject(m.pixels1[i]));
    all.push_back(static_cast<int>(i));
    EXPECT_NEAR(sampson_distance(essential_from_pose(truth), rays0[i], rays1[i]), 0.0, 1e-10);
  }
  const SE3d start =
      SE3d::exp((Eigen::Matrix<double, 6, 1>() << 0.02, -0.01, 0.01, 0.4 * kDeg, -0.3 * kDeg, 0.2 * kDeg).finished()) *
      truth;
  const SE3d refined = refine_relative_pose(start, rays0, rays1, all, {500.0, 1.0, 30});
  EXPECT_GT(test::rotation_error_deg(start, truth), 0.3);
  EXPECT_LT(test::rotation_error_deg(refined, truth), 1e-4);
  EXPECT_LT(test::direction_error_deg(refined.translation(), truth.translation()), 1e-3);
  EXPECT_NEAR(refined.translation().norm(), start.translation().norm(), 1e-12);  // |t| is kept
}

TEST(EssentialRefinement, LeavesAZeroTranslationAlone) {
  const SE3d pure_rotation(SO3<double>::exp(Eigen::Vector3d(0.0, 0.1, 0.0)), Eigen::Vector3d::Zero());
  const std::vector<Eigen::Vector3d> rays(10, Eigen::Vector3d(0.1, 0.1, 1.0));
  const std::vector<int> all{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  const SE3d out = refine_relative_pose(pure_rotation, rays, rays, all, {});
  EXPECT_EQ(out.matrix(), pure_rotation.matrix());
}

TEST(HomographyRefinement, RecoversAPerturbedHomography) {
  Eigen::Matrix3d H;
  H << 1.01, 0.02, 0.05, -0.015, 0.98, -0.02, 0.03, -0.01, 1.0;  // normalised coordinates
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  std::vector<Eigen::Vector2d> x0, x1;
  std::vector<int> all;
  for (int i = 0; i < 100; ++i) {
    Eigen::Vector2d x;
    x << u(rng), u(rng);  // drawn in order (a call's arguments would be in the compiler's)
    x0.push_back(x);
    x1.push_back((H * x0.back().homogeneous()).hnormalized());
    all.push_back(i);
  }
  Eigen::Matrix3d start = H;
  start(0, 2) += 0.01;
  start(2, 0) -= 0.01;
  const Eigen::Matrix3d refined = refine_homography(start, x0, x1, all, 0.01);
  EXPECT_NEAR(refined.norm(), 1.0, 1e-12);
  // Equal up to scale (and sign).
  const Eigen::Matrix3d truth = H / H.norm();
  const double sign = refined.cwiseProduct(truth).sum() < 0.0 ? -1.0 : 1.0;
  EXPECT_LT((sign * refined - truth).norm(), 1e-8);
}

TEST(HomographyRefinement, TooFewMatchesOnlyNormalise) {
  const Eigen::Matrix3d H = 2.0 * Eigen::Matrix3d::Identity();
  const std::vector<Eigen::Vector2d> x(3, Eigen::Vector2d(0.1, 0.2));
  const Eigen::Matrix3d out = refine_homography(H, x, x, {0, 1, 2}, 0.01);
  EXPECT_LT((out - Eigen::Matrix3d::Identity() / std::sqrt(3.0)).norm(), 1e-15);
}

// ---- options -------------------------------------------------------------

TEST(TwoViewOptions, DefaultsAreValid) {
  EXPECT_NO_THROW(validate(TwoViewOptions{}));
  EXPECT_NO_THROW(validate(CornerTrackOptions{}));
}

TEST(TwoViewOptions, EachOutOfRangeValueIsNamed) {
  const std::vector<std::pair<std::string, std::function<void(TwoViewOptions&)>>> cases{
      {"min_tracks", [](TwoViewOptions& o) { o.min_tracks = 7; }},
      {"min_image_motion_fraction", [](TwoViewOptions& o) { o.min_image_motion_fraction = -0.1; }},
      {"match_sigma_px", [](TwoViewOptions& o) { o.match_sigma_px = std::nan(""); }},
      {"ransac_confidence", [](TwoViewOptions& o) { o.ransac_confidence = 1.0; }},
      {"ransac_max_iterations", [](TwoViewOptions& o) { o.ransac_max_iterations = 0; }},
      {"homography_ratio_threshold", [](TwoViewOptions& o) { o.homography_ratio_threshold = 0.0; }},
      {"min_point_parallax_deg", [](TwoViewOptions& o) { o.min_point_parallax_deg = 90.0; }},
      {"min_median_parallax_deg", [](TwoViewOptions& o) { o.min_median_parallax_deg = -1.0; }},
      {"max_reprojection_error_px", [](TwoViewOptions& o) { o.max_reprojection_error_px = 0.0; }},
      {"min_points", [](TwoViewOptions& o) { o.min_points = 3; }},
      {"min_triangulated_fraction", [](TwoViewOptions& o) { o.min_triangulated_fraction = 1.1; }},
      {"ambiguity_ratio", [](TwoViewOptions& o) { o.ambiguity_ratio = 0.0; }},
      {"pure_rotation_max_translation", [](TwoViewOptions& o) { o.pure_rotation_max_translation = -0.01; }},
      {"tracking.max_corners", [](TwoViewOptions& o) { o.tracking.max_corners = 0; }},
      {"tracking.spread_cell_px", [](TwoViewOptions& o) { o.tracking.spread_cell_px = 1; }},
      {"tracking.max_iterations", [](TwoViewOptions& o) { o.tracking.max_iterations = 0; }},
      {"tracking.epsilon", [](TwoViewOptions& o) { o.tracking.epsilon = 0.0; }},
  };
  for (const auto& [name, spoil] : cases) {
    TwoViewOptions options;
    spoil(options);
    const std::string message = error_of([&] { validate(options); });
    EXPECT_NE(message.find("option " + name + ":"), std::string::npos) << name << " -> " << message;
  }
}

}  // namespace
}  // namespace facadeslam
