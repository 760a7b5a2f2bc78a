#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "sequences/synth/camera_path.hpp"

namespace facadeslam::synth {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

StartSpec start_at(double heading_deg) {
  StartSpec s;
  s.position = {1.0, 2.0, 1.6};
  s.heading_deg = heading_deg;
  return s;
}

SegmentSpec segment(SegmentType type, double duration) {
  SegmentSpec s;
  s.type = type;
  s.duration = duration;
  return s;
}

double angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle();
}

TEST(CameraPose, HeadingZeroLooksAlongXWithImageDownAlongMinusZ) {
  const Eigen::Isometry3d T = camera_pose({0, 0, 1.6}, 0.0, 0.0, 0.0);
  EXPECT_TRUE(T.linear().col(2).isApprox(Eigen::Vector3d::UnitX()));   // optical axis
  EXPECT_TRUE(T.linear().col(0).isApprox(-Eigen::Vector3d::UnitY()));  // image right
  EXPECT_TRUE(T.linear().col(1).isApprox(-Eigen::Vector3d::UnitZ()));  // image down
  const Eigen::Isometry3d left = camera_pose({0, 0, 0}, 90 * kDegree, 0.0, 0.0);
  EXPECT_TRUE(left.linear().col(2).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  const Eigen::Isometry3d up = camera_pose({0, 0, 0}, 0.0, 30 * kDegree, 0.0);
  EXPECT_GT(up.linear().col(2).z(), 0.49);  // pitched up
  EXPECT_NEAR(T.linear().determinant(), 1.0, 1e-12);
}

TEST(CameraPath, PanMovesAlongTheCameraRightAxisOnly) {
  SegmentSpec pan = segment(SegmentType::pan, 2.0);
  pan.distance = 0.8;
  const CameraPath path(start_at(30), {pan}, {}, 1);
  const Eigen::Isometry3d a = path.T_w_c(0.0), b = path.T_w_c(2.0);
  const Eigen::Vector3d moved = b.translation() - a.translation();
  EXPECT_NEAR(moved.norm(), 0.8, 1e-12);
  EXPECT_NEAR(moved.normalized().dot(a.linear().col(0)), 1.0, 1e-12);  // along image right
  EXPECT_NEAR(angle_between(a.linear(), b.linear()), 0.0, 1e-12);
  // Eased: at rest at both ends (symmetric finite differences ~ 0).
  EXPECT_LT((path.T_w_c(1e-4).translation() - a.translation()).norm(), 1e-6);
}

TEST(CameraPath, WalkCoversSpeedTimesDurationInItsDirection) {
  SegmentSpec walk = segment(SegmentType::walk, 3.0);
  walk.speed = 1.5;
  walk.direction_deg = -30;
  walk.ease = false;
  const CameraPath path(start_at(30), {walk}, {}, 1);
  const Eigen::Vector3d moved = path.T_w_c(3.0).translation() - path.T_w_c(0.0).translation();
  EXPECT_NEAR(moved.x(), 4.5, 1e-12);  // heading 30 + direction -30: along +x
  EXPECT_NEAR(moved.y(), 0.0, 1e-12);
  // Constant rate without easing.
  EXPECT_NEAR((path.T_w_c(1.0).translation() - path.T_w_c(0.0).translation()).x(), 1.5, 1e-12);
}

TEST(CameraPath, ArcTurnsTheHeadingAndStaysOnItsCircle) {
  SegmentSpec arc = segment(SegmentType::arc, 4.0);
  arc.radius = 5.0;
  arc.angle_deg = 90.0;
  const CameraPath path(start_at(0), {arc}, {}, 1);
  const Eigen::Vector3d centre(1.0, 7.0, 1.6);  // 5 m to the left of (1, 2)
  for (double t : {0.0, 1.0, 2.5, 4.0}) EXPECT_NEAR((path.T_w_c(t).translation() - centre).norm(), 5.0, 1e-9);
  EXPECT_TRUE(path.T_w_c(4.0).linear().col(2).isApprox(Eigen::Vector3d::UnitY(), 1e-9));
  EXPECT_TRUE(path.T_w_c(4.0).translation().isApprox(Eigen::Vector3d(6.0, 7.0, 1.6), 1e-9));
}

TEST(CameraPath, RotateIsAPureRotationEvenWithHandheldJitter) {
  SegmentSpec walk = segment(SegmentType::walk, 1.0);
  SegmentSpec rotate = segment(SegmentType::rotate, 2.0);
  rotate.yaw_deg = 40;
  rotate.pitch_deg = 10;
  JitterSpec handheld;
  handheld.translation = 0.01;
  handheld.rotation_deg = 0.3;
  const CameraPath path(start_at(0), {walk, rotate, walk}, handheld, 5);
  // Within the rotation the hand-held translation is faded out (it fades
  // over the half second before and after): the centre does not move.
  const Eigen::Vector3d centre = path.T_w_c(1.0).translation();
  for (double t = 1.0; t <= 3.0; t += 0.1) EXPECT_LT((path.T_w_c(t).translation() - centre).norm(), 1e-12) << t;
  EXPECT_GT(angle_between(path.T_w_c(1.0).linear(), path.T_w_c(3.0).linear()), 35 * kDegree);
  // The walks on either side do feel the jitter.
  EXPECT_GT((path.T_w_c(0.3).translation() - path.T_w_c(0.3 + 1e-3).translation()).norm(), 0.0);
}

TEST(CameraPath, ShakeReturnsToItsPoseAndStaysWithinItsAmplitude) {
  SegmentSpec shake = segment(SegmentType::shake, 3.0);
  shake.translation = 0.02;
  shake.rotation_deg = 1.0;
  shake.frequency = 3.0;
  const CameraPath path(start_at(0), {shake}, {}, 9);
  const Eigen::Isometry3d rest = path.T_w_c(0.0);
  EXPECT_LT((path.T_w_c(3.0).translation() - rest.translation()).norm(), 1e-12);
  double largest = 0.0;
  for (double t = 0.0; t <= 3.0; t += 0.01) {
    const Eigen::Isometry3d T = path.T_w_c(t);
    const double moved = (T.translation() - rest.translation()).norm();
    largest = std::max(largest, moved);
    EXPECT_LE(moved, 0.02 * std::sqrt(3.0) + 1e-12);
    EXPECT_LE(angle_between(T.linear(), rest.linear()), 1.0 * kDegree * std::sqrt(3.0) + 1e-12);
  }
  EXPECT_GT(largest, 0.005);  // it does shake
}

TEST(CameraPath, SegmentsChainContinuouslyAndTimeIsClamped) {
  SegmentSpec pan = segment(SegmentType::pan, 1.0);
  pan.distance = 0.5;
  SegmentSpec walk = segment(SegmentType::walk, 2.0);
  SegmentSpec arc = segment(SegmentType::arc, 2.0);
  arc.angle_deg = -45;
  SegmentSpec rotate = segment(SegmentType::rotate, 1.0);
  rotate.yaw_deg = 20;
  const CameraPath path(start_at(10), {pan, walk, arc, rotate}, {}, 2);
  EXPECT_DOUBLE_EQ(path.duration(), 6.0);
  for (double boundary : {1.0, 3.0, 5.0}) {
    const Eigen::Isometry3d before = path.T_w_c(boundary - 1e-7), after = path.T_w_c(boundary + 1e-7);
    EXPECT_LT((before.translation() - after.translation()).norm(), 1e-6) << boundary;
    EXPECT_LT(angle_between(before.linear(), after.linear()), 1e-6) << boundary;
  }
  EXPECT_TRUE(path.T_w_c(-1.0).isApprox(path.T_w_c(0.0)));
  EXPECT_TRUE(path.T_w_c(99.0).isApprox(path.T_w_c(6.0)));
}

TEST(CameraPath, SameSeedSamePathOtherSeedOtherJitter) {
  JitterSpec handheld;
  handheld.translation = 0.005;
  handheld.rotation_deg = 0.2;
  const std::vector<SegmentSpec> walk = {segment(SegmentType::walk, 2.0)};
  const CameraPath a(start_at(0), walk, handheld, 4), b(start_at(0), walk, handheld, 4),
      c(start_at(0), walk, handheld, 5);
  EXPECT_TRUE(a.T_w_c(0.77).isApprox(b.T_w_c(0.77), 0.0));
  EXPECT_FALSE(a.T_w_c(0.77).isApprox(c.T_w_c(0.77), 1e-9));
}

}  // namespace
}  // namespace facadeslam::synth
