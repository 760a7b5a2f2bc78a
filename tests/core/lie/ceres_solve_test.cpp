// End-to-end: Ceres auto-differentiates cost functors written with SE3<Jet> /
// Sim3<Jet> and optimises parameter blocks living on SE3Manifold /
// Sim3Manifold, recovering known transforms from exact correspondences.
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <gtest/gtest.h>

#include "core/lie/manifolds.hpp"
#include "tests/core/lie/lie_test_utils.hpp"

namespace facadeslam {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using test::Random;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Vector7d = Eigen::Matrix<double, 7, 1>;

// Normalised image coordinates of a world point: (x/z, y/z) of T_c_w * p_w.
struct ReprojectionError {
  Vector3d point_w;
  Vector2d observed;

  template <class T>
  bool operator()(const T* pose_params, T* residual) const {
    const SE3<T> T_c_w = se3_from_params(pose_params);
    const Eigen::Matrix<T, 3, 1> p_c = T_c_w * point_w.cast<T>();
    residual[0] = p_c.x() / p_c.z() - T(observed.x());
    residual[1] = p_c.y() / p_c.z() - T(observed.y());
    return true;
  }
};

// 3D-3D: T_b_a * p_a - p_b.
struct PointToPointError {
  Vector3d point_a;
  Vector3d point_b;

  template <class T>
  bool operator()(const T* pose_params, T* residual) const {
    const SE3<T> T_b_a = se3_from_params(pose_params);
    Eigen::Map<Eigen::Matrix<T, 3, 1>> r(residual);
    r = T_b_a * point_a.cast<T>() - point_b.cast<T>();
    return true;
  }
};

// Similarity: S_b_a * p_a - p_b.
struct SimilarityError {
  Vector3d point_a;
  Vector3d point_b;

  template <class T>
  bool operator()(const T* sim_params, T* residual) const {
    const Sim3<T> S_b_a = sim3_from_params(sim_params);
    Eigen::Map<Eigen::Matrix<T, 3, 1>> r(residual);
    r = S_b_a * point_a.cast<T>() - point_b.cast<T>();
    return true;
  }
};

ceres::Solver::Summary solve(ceres::Problem& problem) {
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-20;
  options.gradient_tolerance = 1e-20;
  options.parameter_tolerance = 1e-20;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  return summary;
}

SE3d random_pose(Random& rng) {
  Vector6d xi;
  xi << rng.vector3(2.0), rng.rotation_vector();
  return SE3d::exp(xi);
}

TEST(CeresSolve, RecoversACameraPoseFrom3D2DCorrespondences) {
  Random rng(81);
  for (int trial = 0; trial < 5; ++trial) {
    const SE3d T_c_w_true = random_pose(rng);
    ceres::Problem problem;
    double params[kSe3ParamSize];
    // Start 0.3 rad and ~0.3 units away, updated on the left like the tracker.
    Vector6d offset;
    offset << rng.vector3(0.2), rng.unit_vector() * 0.3;
    se3_to_params(SE3d::exp(offset) * T_c_w_true, params);
    for (int i = 0; i < 40; ++i) {
      const double depth = rng.uniform(2.0, 6.0);
      const Vector3d p_c(rng.uniform(-0.5, 0.5) * depth, rng.uniform(-0.4, 0.4) * depth, depth);
      const Vector3d p_w = T_c_w_true.inverse() * p_c;
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<ReprojectionError, 2, kSe3ParamSize>(
                                   new ReprojectionError{p_w, p_c.head<2>() / p_c.z()}),
                               nullptr, params);
    }
    problem.SetManifold(params, new SE3Manifold);
    const ceres::Solver::Summary summary = solve(problem);
    ASSERT_TRUE(summary.IsSolutionUsable()) << summary.FullReport();
    EXPECT_GT(summary.iterations.size(), 2u);
    const SE3d T_c_w = se3_from_params(params);
    EXPECT_LT((T_c_w * T_c_w_true.inverse()).log().norm(), 1e-8) << summary.BriefReport();
    EXPECT_NEAR(Eigen::Map<const Eigen::Vector4d>(params).norm(), 1.0, 1e-14);
  }
}

TEST(CeresSolve, RecoversARigidTransformFrom3D3DCorrespondences) {
  Random rng(82);
  for (int trial = 0; trial < 5; ++trial) {
    const SE3d T_b_a_true = random_pose(rng);
    ceres::Problem problem;
    double params[kSe3ParamSize];
    Vector6d offset;
    offset << rng.vector3(1.0), rng.unit_vector() * 1.5;  // a large initial rotation error
    se3_to_params(SE3d::exp(offset) * T_b_a_true, params);
    for (int i = 0; i < 20; ++i) {
      const Vector3d p_a = rng.vector3(3.0);
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PointToPointError, 3, kSe3ParamSize>(
                                   new PointToPointError{p_a, T_b_a_true * p_a}),
                               nullptr, params);
    }
    problem.SetManifold(params, new SE3Manifold);
    const ceres::Solver::Summary summary = solve(problem);
    ASSERT_TRUE(summary.IsSolutionUsable()) << summary.FullReport();
    const SE3d T_b_a = se3_from_params(params);
    EXPECT_LT((T_b_a * T_b_a_true.inverse()).log().norm(), 1e-8) << summary.BriefReport();
  }
}

TEST(CeresSolve, RecoversASimilarityAligningTwoPointSets) {
  Random rng(83);
  for (int trial = 0; trial < 5; ++trial) {
    Vector7d xi;
    xi << rng.vector3(3.0), rng.rotation_vector(), rng.uniform(-1.5, 1.5);
    const Sim3d S_b_a_true = Sim3d::exp(xi);
    ceres::Problem problem;
    double params[kSim3ParamSize];
    Vector7d offset;
    offset << rng.vector3(1.0), rng.unit_vector() * 0.8, 0.7;
    sim3_to_params(Sim3d::exp(offset) * S_b_a_true, params);
    for (int i = 0; i < 20; ++i) {
      const Vector3d p_a = rng.vector3(3.0);
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<SimilarityError, 3, kSim3ParamSize>(
                                   new SimilarityError{p_a, S_b_a_true * p_a}),
                               nullptr, params);
    }
    problem.SetManifold(params, new Sim3Manifold);
    const ceres::Solver::Summary summary = solve(problem);
    ASSERT_TRUE(summary.IsSolutionUsable()) << summary.FullReport();
    const Sim3d S_b_a = sim3_from_params(params);
    EXPECT_LT((S_b_a * S_b_a_true.inverse()).log().norm(), 1e-8) << summary.BriefReport();
    EXPECT_NEAR(S_b_a.scale(), S_b_a_true.scale(), 1e-9 * S_b_a_true.scale());
  }
}

}  // namespace
}  // namespace facadeslam
