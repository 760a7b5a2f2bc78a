#include "core/trajectory/metrics.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "tests/core/trajectory/synthetic_trajectories.hpp"

namespace facadeslam {
namespace {

using ::testing::HasSubstr;

// Timestamps moved by up to ±4 ms, a deterministic pattern below max_dt.
Trajectory jittered(Trajectory trajectory) {
  for (std::size_t i = 0; i < trajectory.size(); ++i)
    trajectory[i].timestamp += 0.004 * std::sin(1.7 * static_cast<double>(i));
  return trajectory;
}

TEST(EvaluateTrajectory, RecoversAKnownSimilarityExactly) {
  const auto gt = test::helix(120);
  const test::Similarity s{0.37, test::some_rotation(), Eigen::Vector3d(4.0, -1.0, 2.5)};
  const auto est = jittered(test::transformed(gt, s));

  const auto e = evaluate_trajectory(gt, est, {AlignmentMode::sim3});
  EXPECT_EQ(e.pairs, 120u);
  // gt = (1/s) R^T (est - t)
  EXPECT_NEAR(e.scale, 1.0 / 0.37, 1e-9);
  EXPECT_LT((e.alignment.R - s.R.transpose()).norm(), 1e-9);
  EXPECT_LT((e.alignment.t - (-s.R.transpose() * s.t / 0.37)).norm(), 1e-9);
  EXPECT_LT(e.ate_rmse_m, 1e-9);
  EXPECT_LT(e.ate_max_m, 1e-9);
  EXPECT_LT(e.rpe_trans_rmse_m, 1e-9);
  EXPECT_LT(e.rpe_rot_rmse_deg, 1e-6);
  ASSERT_EQ(e.aligned_est_positions.size(), 120u);
  EXPECT_LT((e.aligned_est_positions[7] - gt[7].T_w_c.translation()).norm(), 1e-9);
  EXPECT_EQ(e.timestamps[7], est[7].timestamp);

  // The same data under SE(3): the scale difference stays as error, in both
  // ATE and in RPE's translation, but not in RPE's rotation.
  const auto rigid = evaluate_trajectory(gt, est, {AlignmentMode::se3});
  EXPECT_EQ(rigid.scale, 1.0);
  EXPECT_GT(rigid.ate_rmse_m, 0.1);
  EXPECT_GT(rigid.rpe_trans_rmse_m, 0.1);
  EXPECT_LT(rigid.rpe_rot_rmse_deg, 1e-6);
}

TEST(EvaluateTrajectory, Se3AlignmentOfANoisyCopy) {
  const auto gt = test::helix(200);
  const test::Similarity s{1.0, test::some_rotation(), Eigen::Vector3d(-3.0, 2.0, 1.0)};
  auto est = test::transformed(gt, s);
  std::mt19937 rng(42);
  const double sigma = 0.01;
  std::normal_distribution<double> noise(0.0, sigma);
  for (auto& pose : est) {
    Eigen::Vector3d offset;
    offset << noise(rng), noise(rng), noise(rng);  // drawn in order (a call's arguments would not be)
    pose.T_w_c.translation() += offset;
  }

  const auto e = evaluate_trajectory(gt, est, {AlignmentMode::se3});
  EXPECT_EQ(e.scale, 1.0);
  EXPECT_LT((e.alignment.R - s.R.transpose()).norm(), 0.01);
  EXPECT_LT((e.alignment.t - (-s.R.transpose() * s.t)).norm(), 0.02);
  // Isotropic noise of σ per axis: the RMS distance is about σ√3.
  EXPECT_NEAR(e.ate_rmse_m, sigma * std::sqrt(3.0), 0.2 * sigma * std::sqrt(3.0));
  EXPECT_LE(e.ate_mean_m, e.ate_rmse_m);
  EXPECT_LE(e.ate_median_m, e.ate_max_m);
  EXPECT_LE(e.ate_rmse_m, e.ate_max_m);
  // Sim(3) has one more degree of freedom: never worse, here hardly better.
  const auto similar = evaluate_trajectory(gt, est, {AlignmentMode::sim3});
  EXPECT_LE(similar.ate_rmse_m, e.ate_rmse_m + 1e-15);
  EXPECT_NEAR(similar.scale, 1.0, 0.01);
}

// est_{i+1} = est_i * M_i * D with M_i the ground-truth motion: every relative
// motion is off by the same D, whatever the rigid alignment.
TEST(EvaluateTrajectory, RpeOfAConstantPerStepError) {
  const auto gt = test::helix(60);
  Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
  D.translation() = Eigen::Vector3d(0.006, -0.008, 0.0);  // 1 cm
  D.linear() =
      Eigen::AngleAxisd(0.5 * std::numbers::pi / 180.0, Eigen::Vector3d(1, 2, 2).normalized()).toRotationMatrix();
  Trajectory est = gt;
  for (std::size_t i = 1; i < gt.size(); ++i)
    est[i].T_w_c = est[i - 1].T_w_c * (gt[i - 1].T_w_c.inverse() * gt[i].T_w_c) * D;

  const auto e = evaluate_trajectory(gt, est, {AlignmentMode::se3});
  EXPECT_NEAR(e.rpe_trans_rmse_m, 0.01, 1e-12);
  EXPECT_NEAR(e.rpe_rot_rmse_deg, 0.5, 1e-9);
  EXPECT_GT(e.ate_rmse_m, 0.01);  // the drift accumulates in ATE
}

// A circle run 1.1 times too large: each estimated motion is 10 % too long.
TEST(EvaluateTrajectory, RpeDeltaAndTheRoleOfScale) {
  Trajectory gt;
  const double step = 2.0 * std::numbers::pi / 40.0;
  for (int i = 0; i < 40; ++i) {
    StampedPose p;
    p.timestamp = 0.1 * i;
    p.T_w_c.linear() = Eigen::AngleAxisd(step * i, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    p.T_w_c.translation() = Eigen::Vector3d(std::cos(step * i), std::sin(step * i), 0.0);
    gt.push_back(p);
  }
  const auto est = test::transformed(gt, {1.1, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()});
  const auto chord = [&](int k) { return 2.0 * std::sin(0.5 * step * k); };

  EvaluationOptions options{AlignmentMode::se3};
  EXPECT_NEAR(evaluate_trajectory(gt, est, options).rpe_trans_rmse_m, 0.1 * chord(1), 1e-12);
  options.rpe_delta = 3;
  EXPECT_NEAR(evaluate_trajectory(gt, est, options).rpe_trans_rmse_m, 0.1 * chord(3), 1e-12);
  options.alignment = AlignmentMode::sim3;  // the scale is found and RPE vanishes
  const auto e = evaluate_trajectory(gt, est, options);
  EXPECT_NEAR(e.scale, 1.0 / 1.1, 1e-12);
  EXPECT_LT(e.rpe_trans_rmse_m, 1e-12);
}

TEST(EvaluateTrajectory, PathLengthAndAtePercentage) {
  // Unit square corners, in the z = 0 plane, visited in order: 3 m of path.
  Trajectory gt;
  const std::vector<Eigen::Vector3d> corners{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    StampedPose p;
    p.timestamp = static_cast<double>(i);
    p.T_w_c.translation() = corners[i];
    gt.push_back(p);
  }
  auto est = gt;
  est[0].T_w_c.translation().z() = 0.1;  // one point off the plane
  const auto e = evaluate_trajectory(gt, est, {AlignmentMode::se3});
  EXPECT_NEAR(e.path_length_m, 3.0, 1e-15);
  EXPECT_GT(e.ate_rmse_m, 0.0);
  EXPECT_NEAR(e.ate_percent_of_path, 100.0 * e.ate_rmse_m / 3.0, 1e-12);
}

TEST(EvaluateTrajectory, ErrorStatistics) {
  const auto s = error_statistics({3.0, 1.0, 4.0, 2.0});
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(30.0 / 4.0));
  EXPECT_DOUBLE_EQ(error_statistics({5.0, 1.0, 2.0}).median, 2.0);
  EXPECT_THROW(error_statistics({}), Error);
}

TEST(EvaluateTrajectory, TooFewPairsIsAnError) {
  const auto gt = test::helix(10);
  auto est = gt;
  for (auto& p : est) p.timestamp += 100.0;  // another clock
  try {
    evaluate_trajectory(gt, est);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("only 0 of 10 estimated poses"));
  }
  EXPECT_THROW(evaluate_trajectory(gt, test::helix(2)), Error);
}

TEST(EvaluateTrajectory, BadRpeDeltaIsAnError) {
  const auto gt = test::helix(10);
  EvaluationOptions options;
  options.rpe_delta = 0;
  EXPECT_THROW(evaluate_trajectory(gt, gt, options), Error);
  options.rpe_delta = 10;
  EXPECT_THAT([&] { evaluate_trajectory(gt, gt, options); },
              ::testing::ThrowsMessage<Error>(HasSubstr("between 1 and 9")));
  options.rpe_delta = 9;
  EXPECT_NO_THROW(evaluate_trajectory(gt, gt, options));
}

TEST(EvaluateTrajectory, AlignmentModeNames) {
  EXPECT_EQ(parse_alignment_mode("sim3"), AlignmentMode::sim3);
  EXPECT_EQ(parse_alignment_mode("se3"), AlignmentMode::se3);
  EXPECT_EQ(to_string(AlignmentMode::se3), "se3");
  EXPECT_THAT([] { parse_alignment_mode("SE3x"); }, ::testing::ThrowsMessage<Error>(HasSubstr("'SE3x'")));
}

TEST(EvaluateTrajectory, JsonHasTheFieldNamesAsKeys) {
  const auto gt = test::helix(20);
  const auto e = evaluate_trajectory(gt, gt);
  const Json j = to_json(e);
  for (const char* key : {"pairs", "scale", "ate_rmse_m", "ate_mean_m", "ate_median_m", "ate_max_m", "rpe_trans_rmse_m",
                          "rpe_rot_rmse_deg", "path_length_m", "ate_percent_of_path"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j.at("pairs").get<double>(), 20.0);
  EXPECT_DOUBLE_EQ(j.at("path_length_m").get<double>(), e.path_length_m);
}

}  // namespace
}  // namespace facadeslam
