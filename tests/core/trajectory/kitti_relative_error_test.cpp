#include "core/trajectory/kitti_relative_error.hpp"

#include <cmath>
#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "tests/core/trajectory/synthetic_trajectories.hpp"

namespace facadeslam {
namespace {

using ::testing::HasSubstr;

// KITTI's camera looks along z; the paths below are driven on the x-z plane.
constexpr double kStepM = 0.1;  // between poses: the segment ends at most this far past L

// `count` poses along z, kStepM apart, the camera facing forward.
std::vector<Eigen::Isometry3d> straight_road(std::size_t count) {
  std::vector<Eigen::Isometry3d> poses(count, Eigen::Isometry3d::Identity());
  for (std::size_t i = 0; i < count; ++i)
    poses[i].translation() = Eigen::Vector3d(0, 0, kStepM * static_cast<double>(i));
  return poses;
}

// `count` poses kStepM apart along a circle of `radius` (a long left bend),
// the camera turning with the road (yaw about y).
Trajectory bend(std::size_t count, double radius) {
  Trajectory trajectory;
  for (std::size_t i = 0; i < count; ++i) {
    const double heading = kStepM * static_cast<double>(i) / radius;
    StampedPose pose;
    pose.timestamp = 0.1 * static_cast<double>(i);
    pose.T_w_c.translation() = Eigen::Vector3d(radius * (1.0 - std::cos(heading)), 0, radius * std::sin(heading));
    pose.T_w_c.linear() = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitY()).toRotationMatrix();
    trajectory.push_back(pose);
  }
  return trajectory;
}

std::vector<Eigen::Isometry3d> poses_of(const Trajectory& trajectory) {
  std::vector<Eigen::Isometry3d> poses;
  for (const auto& p : trajectory) poses.push_back(p.T_w_c);
  return poses;
}

TEST(KittiRelativeError, PathScaledByOnePercentIsOnePercentWithoutAlignment) {
  const auto gt = straight_road(2600);  // 259.9 m: 100 and 200 m segments
  auto est = gt;
  for (auto& pose : est) pose.translation() *= 1.01;

  const KittiRelativeError e = kitti_relative_error(gt, est);
  EXPECT_NEAR(e.path_length_m, 259.9, 1e-9);
  ASSERT_EQ(e.per_length.size(), 2u);
  EXPECT_EQ(e.per_length[0].length_m, 100.0);
  EXPECT_EQ(e.per_length[1].length_m, 200.0);
  // First poses every 10 poses (1 m): from 0..159 m a 100 m segment fits, from 0..59 m a 200 m one.
  EXPECT_EQ(e.per_length[0].pairs, 160u);
  EXPECT_EQ(e.per_length[1].pairs, 60u);
  EXPECT_EQ(e.pairs, 220u);
  // |t_E| = 1 % of the segment, which ends up to one step (0.1 m) past L.
  for (const KittiLengthError& l : e.per_length) {
    EXPECT_NEAR(l.translation_percent, 1.0, 1.0 * kStepM / l.length_m + 1e-9) << l.length_m;
    EXPECT_NEAR(l.rotation_deg_per_100m, 0.0, 1e-9) << l.length_m;
  }
  EXPECT_NEAR(e.translation_percent, 1.0, 0.0011);
}

TEST(KittiRelativeError, ConstantYawDriftIsItsDegreesPer100m) {
  // 0.01 deg of yaw per pose at 0.1 m per pose: 10 deg per 100 m.
  const double drift_deg = 0.01;
  const auto gt = straight_road(5000);  // 499.9 m: 100 ... 400 m segments
  auto est = gt;
  for (std::size_t i = 0; i < est.size(); ++i)
    est[i].linear() =
        Eigen::AngleAxisd(deg_to_rad(drift_deg * static_cast<double>(i)), Eigen::Vector3d::UnitY()).toRotationMatrix();

  const KittiRelativeError e = kitti_relative_error(gt, est);
  ASSERT_EQ(e.per_length.size(), 4u);
  EXPECT_EQ(e.per_length.back().length_m, 400.0);
  for (const KittiLengthError& l : e.per_length)
    // The segment ends up to one pose past L: up to one pose's drift more.
    EXPECT_NEAR(l.rotation_deg_per_100m, 10.0, 100.0 * drift_deg / l.length_m + 1e-9) << l.length_m;
  EXPECT_NEAR(e.rotation_deg_per_100m, 10.0, 0.01);
}

TEST(KittiRelativeError, IdenticalTrajectoriesHaveNoError) {
  const auto gt = poses_of(bend(3500, 150.0));  // 349.9 m round a bend
  const KittiRelativeError e = kitti_relative_error(gt, gt);
  ASSERT_EQ(e.per_length.size(), 3u);
  EXPECT_EQ(e.pairs, 250u + 150u + 50u);
  EXPECT_NEAR(e.translation_percent, 0.0, 1e-9);
  EXPECT_NEAR(e.rotation_deg_per_100m, 0.0, 1e-9);
  for (const KittiLengthError& l : e.per_length) {
    EXPECT_NEAR(l.translation_percent, 0.0, 1e-9);
    EXPECT_NEAR(l.rotation_deg_per_100m, 0.0, 1e-9);
  }
}

TEST(KittiRelativeError, PathShorterThan100mHasNoSegments) {
  const auto gt = straight_road(500);  // 49.9 m
  auto est = gt;
  for (auto& pose : est) pose.translation() *= 2.0;
  const KittiRelativeError e = kitti_relative_error(gt, est);
  EXPECT_FALSE(e.has_segments());
  EXPECT_EQ(e.pairs, 0u);
  EXPECT_TRUE(e.per_length.empty());
  EXPECT_TRUE(std::isnan(e.translation_percent));
  EXPECT_TRUE(std::isnan(e.rotation_deg_per_100m));
  EXPECT_THAT(e.no_segments_reason(),
              HasSubstr("ground-truth path (49.9 m) is not longer than the shortest segment (100 m)"));

  const Json j = to_json(e);
  EXPECT_EQ(j["pairs"], 0);
  EXPECT_TRUE(j["translation_percent"].is_null());
  EXPECT_TRUE(j["rotation_deg_per_100m"].is_null());
  EXPECT_TRUE(j["per_length"].empty());
  EXPECT_THAT(j["no_segments"].get<std::string>(), HasSubstr("49.9 m"));
}

TEST(KittiRelativeError, EmptyAndMismatchedInputs) {
  EXPECT_FALSE(kitti_relative_error({}, {}).has_segments());
  EXPECT_THROW(kitti_relative_error(straight_road(3), straight_road(4)), Error);
}

TEST(KittiRelativeError, JsonHasTheFiguresPerLength) {
  const auto gt = straight_road(2600);
  auto est = gt;
  for (auto& pose : est) pose.translation() *= 1.01;
  const Json j = to_json(kitti_relative_error(gt, est));
  EXPECT_EQ(j["pairs"], 220);
  EXPECT_NEAR(j["translation_percent"].get<double>(), 1.0, 0.0011);
  ASSERT_EQ(j["per_length"].size(), 2u);
  EXPECT_EQ(j["per_length"][1]["length_m"], 200.0);
  EXPECT_EQ(j["per_length"][1]["pairs"], 60);
  EXPECT_NEAR(j["per_length"][1]["translation_percent"].get<double>(), 1.0, 0.0011);
  EXPECT_NEAR(j["per_length"][1]["rotation_deg_per_100m"].get<double>(), 0.0, 1e-9);
  EXPECT_FALSE(j.contains("no_segments"));
}

// The trajectory-level figures use the ATE's association and alignment:
// Sim(3) takes a monocular estimate's scale out, SE(3) leaves it in.
TEST(KittiRelativeErrorAfterAlignment, Sim3RemovesTheScaleSe3KeepsIt) {
  const double radius = 300.0;
  const Trajectory gt = bend(2600, radius);
  const test::Similarity half{0.5, test::some_rotation(), Eigen::Vector3d(4.0, -1.0, 2.5)};
  const Trajectory est = test::transformed(gt, half);

  const TrajectoryEvaluation sim3 = evaluate_trajectory(gt, est, {AlignmentMode::sim3});
  const KittiRelativeError aligned = kitti_relative_error_after_alignment(gt, est, sim3);
  ASSERT_EQ(aligned.pairs, 220u);
  EXPECT_NEAR(aligned.translation_percent, 0.0, 1e-6);
  EXPECT_NEAR(aligned.rotation_deg_per_100m, 0.0, 1e-6);

  // Half the scale: |t_E| is half the chord of the 100 m arc, 50 % x 2R sin(L / 2R) / L.
  const TrajectoryEvaluation se3 = evaluate_trajectory(gt, est, {AlignmentMode::se3});
  const KittiRelativeError rigid = kitti_relative_error_after_alignment(gt, est, se3);
  const double chord_percent = 50.0 * 2.0 * radius * std::sin(100.0 / (2.0 * radius)) / 100.0;
  EXPECT_NEAR(rigid.per_length[0].translation_percent, chord_percent, 50.0 * kStepM / 100.0);
  EXPECT_NEAR(rigid.per_length[0].rotation_deg_per_100m, 0.0, 1e-6);
}

// Association by time: an estimate with a pose every other frame is compared
// at those poses, 10 of them (20 frames) apart.
TEST(KittiRelativeErrorAfterAlignment, UsesTheAssociatedPairsOnly) {
  const Trajectory gt = bend(2600, 300.0);
  Trajectory est;
  for (std::size_t i = 0; i < gt.size(); i += 2) est.push_back(gt[i]);
  const TrajectoryEvaluation e = evaluate_trajectory(gt, est, {AlignmentMode::sim3});
  ASSERT_EQ(e.pairs, 1300u);
  const KittiRelativeError k = kitti_relative_error_after_alignment(gt, est, e);
  // First poses 2 m apart: from 0..158 m a 100 m segment fits, from 0..58 m a 200 m one.
  ASSERT_EQ(k.per_length.size(), 2u);
  EXPECT_EQ(k.per_length[0].pairs, 80u);
  EXPECT_EQ(k.per_length[1].pairs, 30u);
  EXPECT_NEAR(k.translation_percent, 0.0, 1e-6);
}

}  // namespace
}  // namespace facadeslam
