// The auto-differentiated residual: value, derivatives (against numeric
// differentiation on the SE3 manifold), and the depth clamp for points behind
// or beside the camera.
#include "mapmaker/ba/reprojection_cost.hpp"

#include <limits>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/gradient_checker.h>
#include <gtest/gtest.h>

#include "core/lie/manifolds.hpp"
#include "tests/mapmaker/ba/ba_test_utils.hpp"

namespace facadeslam {
namespace {

template <class Model>
std::unique_ptr<ceres::CostFunction> cost_for(const Model& model, const Eigen::Vector2d& pixel, int level) {
  return std::make_unique<ceres::AutoDiffCostFunction<ReprojectionCost<Model>, 2, kSe3ParamSize, 3>>(
      new ReprojectionCost<Model>(model, pixel, level));
}

struct Evaluation {
  Eigen::Vector2d residual;
  Eigen::Matrix<double, 2, 7, Eigen::RowMajor> d_pose;
  Eigen::Matrix<double, 2, 3, Eigen::RowMajor> d_point;
};

Evaluation evaluate(const ceres::CostFunction& cost, const SE3d& T_c_w, const Eigen::Vector3d& p_w) {
  double pose[kSe3ParamSize];
  se3_to_params(T_c_w, pose);
  const double* parameters[] = {pose, p_w.data()};
  Evaluation e;
  double* jacobians[] = {e.d_pose.data(), e.d_point.data()};
  EXPECT_TRUE(cost.Evaluate(parameters, e.residual.data(), jacobians));
  return e;
}

const SE3d kPose = SE3d::exp((SE3d::Tangent() << 0.3, -0.2, 0.5, 0.1, -0.05, 0.2).finished());

TEST(ReprojectionCost, IsTheWhitenedPixelError) {
  const Camera camera = test::pinhole_camera();
  const PinholeRadTan& model = std::get<PinholeRadTan>(camera.model());
  const Eigen::Vector3d p_w = kPose.inverse() * Eigen::Vector3d(1.0, -0.5, 6.0);
  const Eigen::Vector2d pixel(300.0, 200.0);
  for (int level : {0, 1, 3}) {
    const Evaluation e = evaluate(*cost_for(model, pixel, level), kPose, p_w);
    const Eigen::Vector2d expected = (camera.project(kPose * p_w) - pixel) / std::ldexp(1.0, level);
    EXPECT_LT((e.residual - expected).norm(), 1e-9) << "level " << level;
  }
}

template <class Model>
void expect_derivatives_match_numeric(const Model& model) {
  const auto cost = cost_for(model, Eigen::Vector2d(310.0, 250.0), 1);
  const SE3Manifold se3;
  std::vector<const ceres::Manifold*> manifolds = {&se3, nullptr};
  ceres::NumericDiffOptions numeric;
  ceres::GradientChecker checker(cost.get(), &manifolds, numeric);
  double pose[kSe3ParamSize];
  se3_to_params(kPose, pose);
  const Eigen::Vector3d p_w = kPose.inverse() * Eigen::Vector3d(-1.5, 0.8, 5.0);
  const double* parameters[] = {pose, p_w.data()};
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(parameters, 1e-7, &results)) << results.error_log;
}

TEST(ReprojectionCost, DerivativesMatchNumericPinhole) {
  expect_derivatives_match_numeric(std::get<PinholeRadTan>(test::pinhole_camera().model()));
}

TEST(ReprojectionCost, DerivativesMatchNumericAtan) {
  expect_derivatives_match_numeric(std::get<AtanCamera>(test::atan_camera().model()));
}

TEST(ClampToField, LeavesPointsInTheFieldAlone) {
  const Eigen::Vector3d p(2.0, -1.0, 0.5);  // 77 degrees off axis: fine
  EXPECT_EQ(clamp_to_field(p), p);
}

TEST(ClampToField, LiftsPointsBehindOrBesideTheCamera) {
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(1.0, 2.0, -3.0), Eigen::Vector3d(0.0, 0.0, -5.0),
                                   Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 0.0)}) {
    const Eigen::Vector3d q = clamp_to_field(p);
    EXPECT_GT(q.z(), 0.0);
    EXPECT_EQ(q.head<2>(), p.head<2>());
    EXPECT_LE(std::abs(q.x() / q.z()), kMaxNormalisedRadius);
    EXPECT_LE(std::abs(q.y() / q.z()), kMaxNormalisedRadius);
  }
}

TEST(ClampToField, IsContinuousAtTheCone) {
  // Just inside and just outside the limiting cone give nearly the same
  // point, so the residual's value is continuous there.
  const double x = 1.0;
  const double z_edge = x / (kMaxNormalisedRadius - 1.0);  // where z = (|x| + |z|) / K
  const Eigen::Vector3d inside = clamp_to_field(Eigen::Vector3d(x, 0, z_edge * (1 + 1e-9)));
  const Eigen::Vector3d outside = clamp_to_field(Eigen::Vector3d(x, 0, z_edge * (1 - 1e-9)));
  EXPECT_NEAR(inside.z(), outside.z(), 1e-8 * z_edge);
}

template <class Model>
void expect_finite_behind(const Model& model) {
  const auto cost = cost_for(model, Eigen::Vector2d(319.5, 239.5), 0);
  const SE3d identity;
  for (const Eigen::Vector3d& p_w : {Eigen::Vector3d(0.5, -0.3, -4.0), Eigen::Vector3d(0.0, 0.0, -2.0),
                                     Eigen::Vector3d(3.0, 0.0, 0.0), Eigen::Vector3d(0.0, 0.0, 0.0)}) {
    const Evaluation e = evaluate(*cost, identity, p_w);
    EXPECT_TRUE(e.residual.allFinite()) << p_w.transpose();
    // Held constant: no pull on the camera or the point.
    EXPECT_TRUE(e.d_pose.isZero(0.0)) << p_w.transpose();
    EXPECT_TRUE(e.d_point.isZero(0.0)) << p_w.transpose();
  }
  // In front, the derivatives are live.
  const Evaluation front = evaluate(*cost, identity, Eigen::Vector3d(0.5, -0.3, 4.0));
  EXPECT_FALSE(front.d_point.isZero(1e-3));
  // Off the axis and behind: a residual far beyond any inlier (the ATAN
  // model compresses large radii, so "far" is ~800 px there).
  EXPECT_GT(evaluate(*cost, identity, Eigen::Vector3d(0.5, -0.3, -4.0)).residual.norm(), 500.0);
}

TEST(ReprojectionCost, FiniteForPointsBehindTheCameraPinhole) {
  expect_finite_behind(std::get<PinholeRadTan>(test::pinhole_camera().model()));
}

TEST(ReprojectionCost, FiniteForPointsBehindTheCameraAtan) {
  expect_finite_behind(std::get<AtanCamera>(test::atan_camera().model()));
}

}  // namespace
}  // namespace facadeslam
