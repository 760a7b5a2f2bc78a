// The ground gauge: the road's plane under the first keyframes, the road
// among one keyframe's points (not the pavement, the parked cars or the
// facades), and the bundle adjustment's ground terms holding the scale.
#include "mapmaker/ground_gauge.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "mapmaker/ba/bundle_adjuster.hpp"

namespace facadeslam {
namespace {

constexpr double kHeight = 1.65;  // KITTI's camera height, metres

// A camera pitched down by 3 degrees and rolled by 1: the road normal in its frame.
Eigen::Vector3d tilted_normal() {
  const Eigen::Matrix3d R_c_road = (Eigen::AngleAxisd(deg_to_rad(3.0), Eigen::Vector3d::UnitX()) *
                                    Eigen::AngleAxisd(deg_to_rad(1.0), Eigen::Vector3d::UnitZ()))
                                       .toRotationMatrix();
  return R_c_road * Eigen::Vector3d::UnitY();
}

// A street in the camera frame of a camera `height` above the road: road
// points ahead, a pavement 0.15 m higher on the right, a facade on the left
// and a parked car's side. Scaled by `scale` (a map's arbitrary units).
std::vector<Eigen::Vector3d> street(std::mt19937& rng, double scale = 1.0, int road = 30, int pavement = 12) {
  const Eigen::Vector3d n = tilted_normal();
  const Eigen::Vector3d forward = (Eigen::Vector3d::UnitZ() - n.z() * n).normalized();
  const Eigen::Vector3d lateral = n.cross(forward);
  std::uniform_real_distribution<double> ahead(3.0, 20.0), across(-3.0, 3.0), up(0.0, 6.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<Eigen::Vector3d> points;
  auto at = [&](double a, double l, double height_below) {
    points.emplace_back(scale * (a * forward + l * lateral + (height_below + noise(rng)) * n));
  };
  for (int i = 0; i < road; ++i) at(ahead(rng), across(rng), kHeight);
  for (int i = 0; i < pavement; ++i) at(ahead(rng), 4.0 + 0.5 * across(rng) / 3.0, kHeight - 0.15);
  for (int i = 0; i < 60; ++i) at(ahead(rng), -6.0, kHeight - up(rng));                          // facade
  for (int i = 0; i < 25; ++i) at(4.0 + across(rng), 2.5, kHeight - 0.3 - 1.1 * up(rng) / 6.0);  // car side
  return points;
}

// Keyframes driving along the camera's forward axis, `step` apart, each seeing `street`.
std::vector<GroundView> driving_views(std::mt19937& rng, double scale, int road = 30, int pavement = 12) {
  const Eigen::Vector3d n = tilted_normal();
  const Eigen::Vector3d forward = (Eigen::Vector3d::UnitZ() - n.z() * n).normalized();
  std::vector<GroundView> views;
  views.reserve(4);
  for (int k = 0; k < 4; ++k) views.push_back({SE3d(SO3d(), -scale * k * forward), street(rng, scale, road, pavement)});
  return views;
}

TEST(GroundGauge, TheReferenceIsTheRoadUnderTheFirstKeyframes) {
  std::mt19937 rng(1);
  const auto reference = fit_ground_reference(driving_views(rng, 0.5), {});
  ASSERT_TRUE(reference);
  EXPECT_NEAR(reference->height, 0.5 * kHeight, 0.01 * 0.5 * kHeight);
  EXPECT_LT(rad_to_deg(std::acos(std::min(1.0, reference->normal_c.dot(tilted_normal())))), 0.5);
}

TEST(GroundGauge, NoReferenceWithoutARoad) {
  std::mt19937 rng(2);
  EXPECT_FALSE(fit_ground_reference(driving_views(rng, 1.0, /*road=*/0, /*pavement=*/0), {}));
  EXPECT_FALSE(fit_ground_reference({}, {}));
}

TEST(GroundGauge, NoReferenceForAHandHeldCamera) {
  // The same road, but the keyframes are raised by 10 % of the height one
  // after the other, or tilted by 5 degrees: not a camera on a vehicle.
  std::mt19937 rng(5);
  std::vector<GroundView> raised = driving_views(rng, 1.0);
  ASSERT_TRUE(fit_ground_reference(raised, {}));
  for (std::size_t k = 0; k < raised.size(); ++k)
    raised[k].T_c_w = SE3d(SO3d(), raised[k].T_c_w.translation() + 0.1 * kHeight * k * tilted_normal());
  EXPECT_FALSE(fit_ground_reference(raised, {}));
  std::vector<GroundView> tilted = driving_views(rng, 1.0);
  tilted[2].T_c_w = SE3d(SO3d::exp(Eigen::Vector3d(deg_to_rad(5.0), 0, 0)), Eigen::Vector3d::Zero()) * tilted[2].T_c_w;
  EXPECT_FALSE(fit_ground_reference(tilted, {}));
}

TEST(GroundGauge, AKeyframesGroundIsTheRoadAtItsScale) {
  std::mt19937 rng(3);
  const GroundReference reference{tilted_normal(), tilted_normal(), kHeight, 100};
  // The map's scale grew by 12 %: the road lies 12 % further below.
  const std::vector<Eigen::Vector3d> points = street(rng, 1.12);
  const auto ground = find_ground(points, reference, kHeight, {});
  ASSERT_TRUE(ground);
  EXPECT_NEAR(ground->height, 1.12 * kHeight, 0.01 * kHeight);
  for (const std::size_t i : ground->inliers) EXPECT_LT(i, 30u) << "a road point, not the pavement or a car";
  EXPECT_GE(ground->inliers.size(), 25u);
  // A scale beyond the search window is not looked for.
  EXPECT_FALSE(find_ground(street(rng, 1.6), reference, kHeight, {}));
}

// A straight drive: keyframes 1 m apart along +z, a camera kHeight above a
// road of points in the world frame (y down), each keyframe measuring the
// road ahead of it.
BaProblem drive(double drift) {
  BaProblem problem;
  for (int k = 0; k < 4; ++k) {
    // The later keyframes' translations are `drift` too long, as a map whose
    // scale grew would have them.
    const double z = k * (k >= 2 ? 1.0 + drift : 1.0);
    problem.keyframes.push_back({static_cast<std::uint64_t>(k), SE3d(SO3d(), Eigen::Vector3d(0, 0, -z)), k == 0});
  }
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> ahead(3.0, 12.0), across(-2.5, 2.5);
  for (int i = 0; i < 40; ++i)
    problem.points.push_back({static_cast<std::uint64_t>(i), Eigen::Vector3d(across(rng), kHeight, ahead(rng)), true});
  for (std::size_t k = 0; k < problem.keyframes.size(); ++k)
    for (std::size_t p = 0; p < problem.points.size(); ++p) problem.observations.push_back({k, p, {0, 0}, 0, 1.0});
  return problem;
}

TEST(GroundGauge, ConstrainsTheFreeKeyframesWithOneKeyframesWorthOfPrior) {
  GroundGaugeOptions options;
  options.reference_keyframes = 1;
  GroundGauge gauge(options);
  BaProblem problem = drive(0.0);
  std::vector<GroundView> views;
  for (const BaKeyFrame& kf : problem.keyframes) {
    views.push_back({kf.T_c_w, {}});
    for (const BaPoint& p : problem.points) views.back().points_c.push_back(kf.T_c_w * p.p_w);
  }
  gauge.try_reference(views.size(), [&] { return views; });
  ASSERT_TRUE(gauge.reference());
  EXPECT_NEAR(gauge.reference()->height, kHeight, 1e-6);

  EXPECT_EQ(gauge.constrain(problem, /*fixed_too=*/false), 3u);  // keyframe 0 is fixed
  double total = 0.0;
  for (const BaGroundObservation& g : problem.ground) {
    EXPECT_NE(g.keyframe, 0u);
    if (g.keyframe == 1) total += g.weight;
  }
  // The shares add up to (point sigma / keyframe sigma)^2: one keyframe's prior.
  const double ratio = options.point_sigma / options.keyframe_sigma;
  EXPECT_NEAR(total, ratio * ratio, 1e-9);
  EXPECT_NO_THROW(validate_ba_problem(problem));

  // A keyframe that looks 8 degrees further up (a hand-held camera, not a
  // mounted one) is left alone: its ground normal is not the reference's.
  BaProblem pitched = drive(0.0);
  pitched.keyframes[2].T_c_w =
      SE3d(SO3d::exp(Eigen::Vector3d(deg_to_rad(8.0), 0, 0)), Eigen::Vector3d::Zero()) * pitched.keyframes[2].T_c_w;
  EXPECT_EQ(gauge.constrain(pitched, /*fixed_too=*/false), 2u);
  for (const BaGroundObservation& g : pitched.ground) EXPECT_NE(g.keyframe, 2u);
  gauge.reset();
  EXPECT_FALSE(gauge.reference());
}

TEST(GroundGauge, TheGroundTermsPullAKeyframeBackToTheRoadsHeight) {
  // Keyframe 3 free and 0.2 m too high: only its ground terms can move it
  // (its reprojection terms pin nothing: the camera below has no pixels).
  BaProblem problem = drive(0.0);
  problem.observations.clear();
  for (auto& kf : problem.keyframes) kf.fixed = true;
  problem.keyframes[3].fixed = false;
  problem.keyframes[3].T_c_w = SE3d(SO3d(), Eigen::Vector3d(0, 0.2, -3.0));
  const Eigen::Vector3d n = Eigen::Vector3d::UnitY();
  for (std::size_t p = 0; p < problem.points.size(); ++p)
    problem.ground.push_back({3, p, n, kHeight, 0.03 * kHeight, 1.0 / 40.0});
  PinholeRadTan model;
  model.fx = model.fy = 500;
  model.cx = 320;
  model.cy = 240;
  BundleAdjuster().solve(problem, Camera(640, 480, model));
  for (const BaPoint& p : problem.points) EXPECT_NEAR(n.dot(problem.keyframes[3].T_c_w * p.p_w), kHeight, 1e-3);
}

TEST(GroundGauge, ABadGroundObservationIsRejected) {
  BaProblem problem = drive(0.0);
  problem.ground.push_back({1, 0, Eigen::Vector3d(0, 2, 0), kHeight, 0.05, 1.0});
  EXPECT_THROW(validate_ba_problem(problem), Error);
  problem.ground.back().normal_c = Eigen::Vector3d::UnitY();
  problem.ground.back().sigma = 0.0;
  EXPECT_THROW(validate_ba_problem(problem), Error);
  problem.ground.back().sigma = 0.05;
  problem.ground.back().point = 99;
  EXPECT_THROW(validate_ba_problem(problem), Error);
}

}  // namespace
}  // namespace facadeslam
