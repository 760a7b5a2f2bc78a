#include "calib/atan_calibration.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <variant>

#include <ceres/autodiff_cost_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <spdlog/spdlog.h>

#include "calib/atan_projection.hpp"
#include "core/lie/manifolds.hpp"
#include "core/util/error.hpp"

namespace facadeslam::calib {
namespace {

// Largest w the fit may reach; camera files accept [0, 3) and a lens whose
// 90-degree field does not cover the image cannot be loaded anyway.
constexpr double kMaxW = 2.9;

struct CornerResidual {
  Eigen::Vector3d p_b;
  Eigen::Vector2d observed;
  bool tie_focal;

  template <class T>
  bool operator()(const T* intrinsics, const T* pose_params, T* residual) const {
    const SE3<T> T_c_b = se3_from_params(pose_params);
    const Eigen::Matrix<T, 3, 1> p_c = T_c_b * p_b.cast<T>();
    if (!(p_c(2) > 0.0)) return false;  // a step that puts the board behind the camera is rejected
    const Eigen::Matrix<T, 2, 1> px = atan_project(intrinsics, p_c, tie_focal);
    residual[0] = px(0) - observed(0);
    residual[1] = px(1) - observed(1);
    return true;
  }
};

}  // namespace

std::vector<double> atan_start_from_pinhole(const PinholeRadTan& pinhole, bool tie_focal) {
  // k1 ~ -a^2 / 3 with a = 2 tan(w/2); barrel distortion gives k1 < 0. For
  // pincushion (k1 >= 0), which the FOV model cannot represent, start small.
  const double a = pinhole.k1 < 0.0 ? std::sqrt(-3.0 * pinhole.k1) : 0.0;
  const double w = std::clamp(2.0 * std::atan(0.5 * a), 0.05, 2.0);
  const double slope = atan_tan_half_ratio(w);
  const double fx = pinhole.fx / slope;
  const double fy = tie_focal ? fx : pinhole.fy / slope;
  return {fx, fy, pinhole.cx, pinhole.cy, w};
}

CalibrationResult calibrate_atan(const std::vector<AcceptedView>& views, const CalibrationResult& pinhole_start,
                                 const BoardSpec& board, const FitOptions& options) {
  const auto* pinhole = std::get_if<PinholeRadTan>(&pinhole_start.camera.model());
  if (pinhole == nullptr || pinhole_start.T_c_b.size() != views.size())
    throw Error("calibrate_atan: expected a pinhole calibration of the same views as the start");

  std::vector<double> intrinsics = atan_start_from_pinhole(*pinhole, options.fix_aspect);
  std::vector<std::array<double, kSe3ParamSize>> poses(views.size());
  for (std::size_t v = 0; v < views.size(); ++v) se3_to_params(pinhole_start.T_c_b[v], poses[v].data());

  ceres::Problem problem;
  for (std::size_t v = 0; v < views.size(); ++v) {
    for (int k = 0; k < board.corner_count(); ++k) {
      const cv::Point2f& c = views[v].corners[k];
      auto* cost = new ceres::AutoDiffCostFunction<CornerResidual, 2, kAtanIntrinsicCount, kSe3ParamSize>(
          new CornerResidual{board_corner(board, k), Eigen::Vector2d(c.x, c.y), options.fix_aspect});
      problem.AddResidualBlock(cost, nullptr, intrinsics.data(), poses[v].data());
    }
    problem.SetManifold(poses[v].data(), new SE3Manifold);
  }
  // With a tied focal length fy is unused: hold it constant so the normal
  // equations keep full rank.
  if (options.fix_aspect)
    problem.SetManifold(intrinsics.data(), new ceres::SubsetManifold(kAtanIntrinsicCount, {kAtanFy}));
  problem.SetParameterLowerBound(intrinsics.data(), kAtanW, 0.0);
  problem.SetParameterUpperBound(intrinsics.data(), kAtanW, kMaxW);

  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_SCHUR;
  solver.max_num_iterations = 200;
  solver.function_tolerance = 1e-14;
  solver.gradient_tolerance = 1e-14;
  solver.parameter_tolerance = 1e-14;
  solver.num_threads = 1;  // deterministic, and the machine is shared
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  spdlog::debug("ATAN fit: {}", summary.BriefReport());
  if (!summary.IsSolutionUsable()) throw Error("ATAN calibration failed to converge (" + summary.message + ")");
  if (options.fix_aspect) intrinsics[kAtanFy] = intrinsics[kAtanFx];

  AtanCamera model;
  model.fx = intrinsics[kAtanFx];
  model.fy = intrinsics[kAtanFy];
  model.cx = intrinsics[kAtanCx];
  model.cy = intrinsics[kAtanCy];
  model.w = intrinsics[kAtanW];
  for (double value : intrinsics)
    if (!std::isfinite(value)) throw Error("ATAN calibration returned non-finite parameters (degenerate views?)");
  if (model.fx <= 0.0 || model.fy <= 0.0) throw Error("ATAN calibration returned a focal length <= 0");

  std::vector<SE3d> T_c_b;
  for (const auto& pose : poses) T_c_b.push_back(se3_from_params(pose.data()));
  const Camera& start = pinhole_start.camera;
  return evaluate_calibration(Camera(start.width(), start.height(), model), std::move(T_c_b), views, board);
}

}  // namespace facadeslam::calib
