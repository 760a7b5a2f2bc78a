#include "tracker/pose_update.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "core/util/error.hpp"
#include "tests/support/rendered_plane.hpp"

namespace facadeslam {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

SE3d true_pose() {
  Vector6d xi;
  xi << 0.1, -0.05, 0.2, 0.02, -0.03, 0.01;
  return SE3d::exp(xi);
}

// Points spread over the view at depths 2..6 m, measured exactly (levels 0..3).
std::vector<PoseMeasurement> exact_measurements(const SE3d& T_c_w, const Camera& camera, int n, int seed = 11) {
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  std::vector<PoseMeasurement> m;
  const SE3d T_w_c = T_c_w.inverse();
  while (static_cast<int>(m.size()) < n) {
    // One draw a statement: a call's arguments are evaluated in the compiler's order.
    const double u = rng.uniform(20.0, camera.width() - 20.0);
    const double v = rng.uniform(20.0, camera.height() - 20.0);
    const Eigen::Vector2d px(u, v);
    const Eigen::Vector3d p_c = camera.unproject(px) * rng.uniform(2.0, 6.0);
    PoseMeasurement meas;
    meas.p_w = T_w_c * p_c;
    meas.pixel = camera.project(p_c);
    meas.level = rng.uniform(0, 4);
    m.push_back(meas);
  }
  return m;
}

SE3d perturbed(const SE3d& T) {
  // 0.1 m translation and 0.05 rad rotation, left-multiplied.
  Vector6d xi;
  xi << Eigen::Vector3d(1, -2, 2).normalized() * 0.1, Eigen::Vector3d(-1, 1, 0.5).normalized() * 0.05;
  return SE3d::exp(xi) * T;
}

double rotation_error(const SE3d& a, const SE3d& b) { return (a.so3() * b.so3().inverse()).log().norm(); }
double translation_error(const SE3d& a, const SE3d& b) {
  return (a.inverse().translation() - b.inverse().translation()).norm();  // camera centres
}

TEST(PoseUpdate, RecoversAPerturbedPoseExactly) {
  const Camera camera = test::test_camera();
  const SE3d truth = true_pose();
  const auto m = exact_measurements(truth, camera, 100);
  const PoseUpdateResult r = update_pose(perturbed(truth), m, camera);
  ASSERT_TRUE(r.ok);
  EXPECT_TRUE(r.converged);
  std::printf("[ exact ] rotation error %.2e rad, translation error %.2e m, %d iterations\n",
              rotation_error(r.T_c_w, truth), translation_error(r.T_c_w, truth), r.iterations);
  EXPECT_LT(rotation_error(r.T_c_w, truth), 1e-9);
  EXPECT_LT(translation_error(r.T_c_w, truth), 1e-9);
  EXPECT_EQ(r.num_inliers, 100);
  EXPECT_LT(r.inlier_rms_px, 1e-6);
  EXPECT_DOUBLE_EQ(r.sigma_squared, PoseUpdateOptions{}.min_sigma_squared);  // the floor
  for (double w : r.weights) EXPECT_NEAR(w, 1.0, 1e-9);
}

TEST(PoseUpdate, RejectsGrossOutliersAndStillRecoversThePose) {
  const Camera camera = test::test_camera();
  const SE3d truth = true_pose();
  auto m = exact_measurements(truth, camera, 200);
  cv::RNG rng(3);
  std::vector<bool> is_outlier(m.size(), false);
  for (std::size_t i = 0; i < m.size(); i += 5) {  // 20% moved by 30 px
    const double a = rng.uniform(0.0, 2 * M_PI);
    m[i].pixel += 30.0 * Eigen::Vector2d(std::cos(a), std::sin(a));
    is_outlier[i] = true;
  }
  const PoseUpdateResult r = update_pose(perturbed(truth), m, camera);
  ASSERT_TRUE(r.ok);
  const double rot = rotation_error(r.T_c_w, truth), trans = translation_error(r.T_c_w, truth);
  std::printf("[ 20%% outliers ] rotation error %.2e rad, translation error %.2e m, %d inliers, rms %.2e px\n", rot,
              trans, r.num_inliers, r.inlier_rms_px);
  EXPECT_LT(rot, 1e-3);
  EXPECT_LT(trans, 1e-3);
  for (std::size_t i = 0; i < m.size(); ++i) {
    EXPECT_EQ(r.inliers[i] != 0, !is_outlier[i]) << "measurement " << i;
    if (is_outlier[i]) {
      EXPECT_EQ(r.weights[i], 0.0);
    }
  }
  EXPECT_EQ(r.num_inliers, 160);
  EXPECT_LT(r.inlier_rms_px, 1e-3);
}

TEST(PoseUpdate, NoisyMeasurementsGiveAConsistentScaleAndCovariance) {
  const Camera camera = test::test_camera();
  const SE3d truth = true_pose();
  auto m = exact_measurements(truth, camera, 1000);
  cv::RNG rng(9);
  const double sigma_px = 1.0;  // per axis, in level pixels
  for (auto& meas : m) {
    const double du = rng.gaussian(sigma_px);
    const double dv = rng.gaussian(sigma_px);
    meas.pixel += Eigen::Vector2d(du, dv) * ImagePyramid::level_scale(meas.level);
  }
  const PoseUpdateResult r = update_pose(perturbed(truth), m, camera);
  ASSERT_TRUE(r.ok);
  // The scale estimate recovers sigma^2 = 1 level-pixel^2.
  EXPECT_NEAR(r.sigma_squared, 1.0, 0.15);
  EXPECT_GT(r.num_inliers, 990);
  // The error lies within a few standard deviations of the covariance.
  const Vector6d error = (r.T_c_w * truth.inverse()).log();
  const double mahalanobis2 = error.dot(r.information * error);
  EXPECT_LT(mahalanobis2, 30.0);  // chi-square(6): 99.99% below 27.9 (weights < 1 shrink it a little)
  EXPECT_TRUE((r.covariance * r.information).isApprox(Matrix6d::Identity(), 1e-6));
}

TEST(PoseUpdate, LevelScalesTheInformation) {
  const Camera camera = test::test_camera();
  const SE3d truth = true_pose();
  auto m = exact_measurements(truth, camera, 50);
  for (auto& meas : m) meas.level = 0;
  const PoseUpdateResult r0 = update_pose(truth, m, camera);
  for (auto& meas : m) meas.level = 2;
  const PoseUpdateResult r2 = update_pose(truth, m, camera);
  ASSERT_TRUE(r0.ok && r2.ok);
  EXPECT_TRUE(r0.information.isApprox(16.0 * r2.information, 1e-9));
}

TEST(PoseUpdate, TooFewMeasurementsLeaveThePoseUnchanged) {
  const Camera camera = test::test_camera();
  const SE3d truth = true_pose();
  const SE3d start = perturbed(truth);
  const auto m = exact_measurements(truth, camera, 2);  // 4 equations, 6 unknowns
  const PoseUpdateResult r = update_pose(start, m, camera);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_TRUE(r.T_c_w.matrix().isApprox(start.matrix()));
  const PoseUpdateResult none = update_pose(start, std::vector<PoseMeasurement>{}, camera);
  EXPECT_FALSE(none.ok);
  EXPECT_EQ(none.num_inliers, 0);
}

TEST(PoseUpdate, PointsBehindTheCameraAreIgnored) {
  const Camera camera = test::test_camera();
  const SE3d truth = true_pose();
  auto m = exact_measurements(truth, camera, 60);
  PoseMeasurement behind;
  behind.p_w = truth.inverse() * Eigen::Vector3d(0.1, 0.2, -3.0);
  behind.pixel = {320, 240};
  m.push_back(behind);
  const PoseUpdateResult r = update_pose(perturbed(truth), m, camera);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.inliers.back(), 0);
  EXPECT_EQ(r.weights.back(), 0.0);
  EXPECT_LT(rotation_error(r.T_c_w, truth), 1e-9);
}

// Label-aware tracking: a coherent group of points that moved (a car pulling
// away: 40 % of the measurements shifted by 3 px, too little for Tukey to
// reject) pulls the pose at full weight and hardly at all at weight 0.1.
TEST(PoseUpdate, PriorWeightsLimitWhatDownWeightedPointsCanPull) {
  const Camera camera = test::test_camera();
  const SE3d truth = true_pose();
  auto m = exact_measurements(truth, camera, 200);
  for (std::size_t i = 0; i < m.size(); i += 5)
    for (std::size_t k = i; k < i + 2; ++k) m[k].pixel += Eigen::Vector2d(3.0, 0.0);
  const double full = rotation_error(update_pose(perturbed(truth), m, camera).T_c_w, truth);
  for (std::size_t i = 0; i < m.size(); i += 5)
    for (std::size_t k = i; k < i + 2; ++k) m[k].weight = 0.1;
  const PoseUpdateResult r = update_pose(perturbed(truth), m, camera);
  ASSERT_TRUE(r.ok);
  const double down = rotation_error(r.T_c_w, truth);
  std::printf("[ moving 40%% ] rotation error %.2e rad at full weight, %.2e rad at weight 0.1\n", full, down);
  EXPECT_LT(down, 0.25 * full);
  EXPECT_LE(r.weights[0], 0.1);
  EXPECT_GT(r.weights[2], 0.1);
}

// The tracker builds the measurements: a weight or level out of range is a
// bug (FACADESLAM_ASSERT), not something a user can cause.
TEST(PoseUpdateDeathTest, AWeightOutsideZeroToOneIsAnInternalError) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const Camera camera = test::test_camera();
  auto m = exact_measurements(true_pose(), camera, 10);
  m[3].weight = 1.5;
  EXPECT_DEATH(update_pose(true_pose(), m, camera), "internal error.*prior weight is in \\[0, 1\\]");
  m[3].weight = std::nan("");
  EXPECT_DEATH(update_pose(true_pose(), m, camera), "prior weight");
}

TEST(PoseUpdateDeathTest, ALevelOutsideThePyramidIsAnInternalError) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const Camera camera = test::test_camera();
  auto m = exact_measurements(true_pose(), camera, 10);
  m[3].level = 4;
  EXPECT_DEATH(update_pose(true_pose(), m, camera), "a pyramid level");
  m[3].level = -1;
  EXPECT_DEATH(update_pose(true_pose(), m, camera), "a pyramid level");
}

TEST(PoseMeasurementJacobian, MatchesCentralDifferencesForEveryCameraModel) {
  const std::vector<Camera> cameras = {
      test::test_camera(), Camera(640, 480, PinholeRadTan{480.0, 470.0, 321.0, 243.0, -0.2, 0.05, 0.001, -0.002, 0.01}),
      Camera(640, 480, AtanCamera{400.0, 410.0, 318.0, 241.0, 0.9})};
  const SE3d T = true_pose();
  const Eigen::Vector3d p_w = T.inverse() * Eigen::Vector3d(0.4, -0.3, 2.5);
  for (const Camera& camera : cameras) {
    const Eigen::Matrix<double, 2, 6> J = pose_measurement_jacobian(T, p_w, camera);
    Eigen::Matrix<double, 2, 6> numeric;
    const double h = 1e-6;
    for (int k = 0; k < 6; ++k) {
      Vector6d d = Vector6d::Zero();
      d(k) = h;
      numeric.col(k) = (camera.project(SE3d::exp(d) * T * p_w) - camera.project(SE3d::exp(-d) * T * p_w)) / (2 * h);
    }
    EXPECT_TRUE(J.isApprox(numeric, 1e-6)) << camera.model_name() << "\n" << J << "\n" << numeric;
  }
}

TEST(RobustScale, MedianOfSquaredNormsWithAFloor) {
  std::vector<double> e2 = {4.0, 100.0, 1.0, 9.0, 2.0};  // median 4
  EXPECT_NEAR(robust_sigma_squared(e2, 0.4), 4.0 / (2 * std::log(2.0)), 1e-12);
  std::vector<double> tiny = {1e-6, 0.0, 2e-6};
  EXPECT_EQ(robust_sigma_squared(tiny, 0.4), 0.4);
  EXPECT_EQ(robust_sigma_squared({}, 0.4), 0.4);
  EXPECT_EQ(tukey_weight(0.0, 9.0), 1.0);
  EXPECT_NEAR(tukey_weight(4.5, 9.0), 0.25, 1e-15);
  EXPECT_EQ(tukey_weight(9.0, 9.0), 0.0);
  EXPECT_EQ(tukey_weight(std::nan(""), 9.0), 0.0);
}

}  // namespace
}  // namespace facadeslam
