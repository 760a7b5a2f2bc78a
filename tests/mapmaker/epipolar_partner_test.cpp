#include "mapmaker/epipolar_partner.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace facadeslam {
namespace {

// A camera at `centre` (world: z up) looking horizontally at `heading_deg`
// (0 = +x, 90 = +y), as T_c_w.
SE3d camera_at(const Eigen::Vector3d& centre, double heading_deg) {
  const double h = heading_deg * std::numbers::pi / 180.0;
  const Eigen::Vector3d forward(std::cos(h), std::sin(h), 0.0), up(0, 0, 1);
  Eigen::Matrix3d R_w_c;
  R_w_c.col(2) = forward;
  R_w_c.col(1) = -up;  // image y points down
  R_w_c.col(0) = R_w_c.col(1).cross(forward);
  const SE3d T_w_c(R_w_c, centre);
  return T_w_c.inverse();
}

constexpr double kDepth = 10.0;

TEST(EpipolarPartner, NoKeyframesNoPartner) {
  EXPECT_FALSE(choose_epipolar_partner(camera_at({0, 0, 0}, 0), kDepth, {}, {}));
}

TEST(EpipolarPartner, WalkingTakesTheNearestKeyframe) {
  // PTAM's rule when it works: keyframes every metre along the walk.
  const std::vector<SE3d> others = {camera_at({-3, 0, 0}, 0), camera_at({-1, 0, 0}, 0), camera_at({-2, 0, 0}, 0)};
  EXPECT_EQ(choose_epipolar_partner(camera_at({0, 0, 0}, 0), kDepth, others, {}), 1u);
}

TEST(EpipolarPartner, TurningOnTheSpotSkipsKeyframesWithoutBaseline) {
  // Keyframes 0 and 1 stand where the new one stands (turning on the spot);
  // keyframe 2 is 1 m back along the walk, looking 30 degrees away.
  const std::vector<SE3d> others = {camera_at({0, 0, 0}, 0), camera_at({0.01, 0, 0}, 15), camera_at({-1, 0, 0}, 0)};
  EXPECT_EQ(choose_epipolar_partner(camera_at({0, 0, 0}, 30), kDepth, others, {}), 2u);
}

TEST(EpipolarPartner, PrefersAKeyframeThatSharesTheView) {
  // Both have a baseline; the nearer one looks the other way.
  const std::vector<SE3d> others = {camera_at({-0.5, 0, 0}, 180), camera_at({-2, 0, 0}, 10)};
  EXPECT_EQ(choose_epipolar_partner(camera_at({0, 0, 0}, 0), kDepth, others, {}), 1u);
}

TEST(EpipolarPartner, FallsBackToBaselineThenToNearest) {
  // No keyframe shares the view: the nearest with a baseline.
  std::vector<SE3d> others = {camera_at({0, 0, 0}, 90), camera_at({-1, 0, 0}, 180), camera_at({-3, 0, 0}, 180)};
  EXPECT_EQ(choose_epipolar_partner(camera_at({0, 0, 0}, 0), kDepth, others, {}), 1u);
  // No keyframe has a baseline: the nearest.
  others = {camera_at({0.05, 0, 0}, 0), camera_at({0.01, 0, 0}, 0)};
  EXPECT_EQ(choose_epipolar_partner(camera_at({0, 0, 0}, 0), kDepth, others, {}), 1u);
}

TEST(EpipolarPartner, BaselineScalesWithSceneDepth) {
  const std::vector<SE3d> others = {camera_at({-0.1, 0, 0}, 0), camera_at({-1, 0, 0}, 0)};
  // 0.1 m is enough in front of a wall 2 m away (0.02 x 2 = 0.04 m) ...
  EXPECT_EQ(choose_epipolar_partner(camera_at({0, 0, 0}, 0), 2.0, others, {}), 0u);
  // ... but not for a street 10 m deep (0.2 m needed).
  EXPECT_EQ(choose_epipolar_partner(camera_at({0, 0, 0}, 0), 10.0, others, {}), 1u);
}

TEST(EpipolarPartner, FarPartnerIsTheNearestBeyondItsBaselineThatSharesTheView) {
  // Driving forward along x: keyframes 1, 2, 4 and 7 m back, one 5 m back looking sideways.
  const std::vector<SE3d> others = {camera_at({-1, 0, 0}, 0), camera_at({-2, 0, 0}, 0), camera_at({-4, 0, 0}, 0),
                                    camera_at({-5, 0, 0}, 90), camera_at({-7, 0, 0}, 0)};
  EpipolarPartnerOptions options;
  options.far_baseline = 0.0;
  EXPECT_FALSE(choose_far_epipolar_partner(camera_at({0, 0, 0}, 0), kDepth, others, 0, options)) << "0: none";
  options.far_baseline = 0.3;  // 3 m in a street 10 m deep
  EXPECT_EQ(choose_far_epipolar_partner(camera_at({0, 0, 0}, 0), kDepth, others, 0, options), 2u);
  // Never the near partner itself, and nothing when no keyframe is far enough.
  EXPECT_EQ(choose_far_epipolar_partner(camera_at({0, 0, 0}, 0), kDepth, others, 2, options), 4u);
  options.far_baseline = 1.0;
  EXPECT_FALSE(choose_far_epipolar_partner(camera_at({0, 0, 0}, 0), kDepth, others, 0, options));
}

TEST(EpipolarPartner, MovingForwardIsMotionAlongTheOpticalAxis) {
  const EpipolarPartnerOptions options;  // within 10 degrees
  // Looking along +x: driving forward from 1 m back, then sideways from 1 m to the right.
  EXPECT_TRUE(moving_forward(camera_at({0, 0, 0}, 0), camera_at({-1, 0, 0}, 0), options));
  EXPECT_TRUE(moving_forward(camera_at({0, 0, 0}, 0), camera_at({-1, -0.15, 0}, 0), options));  // 8.5 degrees off
  EXPECT_FALSE(moving_forward(camera_at({0, 0, 0}, 0), camera_at({-1, -0.5, 0}, 0),
                              options));  // 27 degrees off (a walk looking aside)
  EXPECT_FALSE(moving_forward(camera_at({0, 0, 0}, 0), camera_at({0, -1, 0}, 0), options));  // a walk along facades
  EXPECT_FALSE(moving_forward(camera_at({0, 0, 0}, 0), camera_at({1, 0, 0}, 0), options));   // backing up
  EXPECT_FALSE(moving_forward(camera_at({0, 0, 0}, 30), camera_at({0, 0, 0}, 0), options));  // turning on the spot
}

}  // namespace
}  // namespace facadeslam
