#include "mapmaker/ba/bundle_adjuster.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <type_traits>

#include <ceres/autodiff_cost_function.h>
#include <ceres/iteration_callback.h>
#include <ceres/loss_function.h>
#include <ceres/ordered_groups.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <spdlog/spdlog.h>

#include "core/lie/manifolds.hpp"
#include "core/util/error.hpp"
#include "mapmaker/ba/centre_distance_manifold.hpp"
#include "mapmaker/ba/ground_height_cost.hpp"
#include "mapmaker/ba/reprojection_cost.hpp"
#include "core/util/stopwatch.hpp"

namespace facadeslam {
namespace {

using PoseBlock = std::array<double, kSe3ParamSize>;
using PointBlock = std::array<double, 3>;

void check_option(bool ok, const std::string& what) {
  if (!ok) throw Error("bundle adjustment options: " + what);
}

std::unique_ptr<ceres::LossFunction> make_loss(BaLoss loss, double scale) {
  switch (loss) {
    case BaLoss::none: return nullptr;
    case BaLoss::huber: return std::make_unique<ceres::HuberLoss>(scale);
    case BaLoss::cauchy: return std::make_unique<ceres::CauchyLoss>(scale);
    case BaLoss::tukey: return std::make_unique<ceres::TukeyLoss>(scale);
  }
  throw Error("bundle adjustment options: unknown loss");
}

// Reads the abort flag (and runs the diagnostics hook) after every Ceres
// iteration. A requested abort ends the solve with
// SOLVER_TERMINATE_SUCCESSFULLY rather than SOLVER_ABORT: Ceres then copies
// the last accepted iterate back, so the work done so far is kept.
class AbortCallback final : public ceres::IterationCallback {
 public:
  AbortCallback(std::atomic<bool>* abort, const std::function<void(int)>& hook) : abort_(abort), hook_(hook) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (hook_) hook_(summary.iteration);
    if (abort_ != nullptr && abort_->load(std::memory_order_acquire)) {
      aborted_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool aborted() const { return aborted_; }

 private:
  std::atomic<bool>* abort_;
  const std::function<void(int)>& hook_;
  bool aborted_ = false;
};

// Reprojection errors of the current state: RMS in level-0 pixels and the
// chi-square outliers.
struct ErrorSummary {
  double rms_px = 0.0;
  double inlier_rms_px = 0.0;
  std::vector<std::size_t> outliers;
};

ErrorSummary measure_errors(const BaProblem& problem, const Camera& camera, double outlier_chi2) {
  ErrorSummary summary;
  double sum_sq = 0.0;
  double inlier_sum_sq = 0.0;
  camera.visit([&](const auto& model) {
    for (std::size_t i = 0; i < problem.observations.size(); ++i) {
      const BaObservation& obs = problem.observations[i];
      const SE3d& T_c_w = problem.keyframes[obs.keyframe].T_c_w;
      const Eigen::Vector3d& p_w = problem.points[obs.point].p_w;
      const double inv_sigma = std::ldexp(1.0, -obs.level);
      const Eigen::Vector2d whitened = whitened_reprojection_residual(model, T_c_w, p_w, obs.pixel, inv_sigma);
      const double error_sq_px = whitened.squaredNorm() / (inv_sigma * inv_sigma);
      sum_sq += error_sq_px;
      const bool behind = (T_c_w * p_w).z() <= 0.0;
      if (behind || whitened.squaredNorm() > outlier_chi2)
        summary.outliers.push_back(i);
      else
        inlier_sum_sq += error_sq_px;
    }
  });
  const std::size_t n = problem.observations.size();
  const std::size_t inliers = n - summary.outliers.size();
  summary.rms_px = n > 0 ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0;
  summary.inlier_rms_px = inliers > 0 ? std::sqrt(inlier_sum_sq / static_cast<double>(inliers)) : 0.0;
  return summary;
}

// The parameter blocks Ceres works on, copied from the problem (so that an
// exception half-way leaves the caller's problem untouched).
struct ParameterBlocks {
  std::vector<PoseBlock> poses;
  std::vector<PointBlock> points;
  std::vector<char> pose_used;  // appears in a residual
  std::vector<char> point_used;

  explicit ParameterBlocks(const BaProblem& problem)
      : poses(problem.keyframes.size()),
        points(problem.points.size()),
        pose_used(problem.keyframes.size(), 0),
        point_used(problem.points.size(), 0) {
    for (std::size_t i = 0; i < poses.size(); ++i) se3_to_params(problem.keyframes[i].T_c_w, poses[i].data());
    for (std::size_t i = 0; i < points.size(); ++i)
      Eigen::Map<Eigen::Vector3d>(points[i].data()) = problem.points[i].p_w;
  }
};

template <class Model>
void add_residuals(ceres::Problem& ceres_problem, const BaProblem& problem, const Model& model,
                   ceres::LossFunction* loss, ParameterBlocks& blocks,
                   std::vector<std::unique_ptr<ceres::LossFunction>>& scaled_losses) {
  for (const BaObservation& obs : problem.observations) {
    // A residual between two constant blocks cannot change: leave it out of
    // the solve (it still counts in the RMS and the outlier test).
    if (problem.keyframes[obs.keyframe].fixed && problem.points[obs.point].fixed) continue;
    auto* cost = new ceres::AutoDiffCostFunction<ReprojectionCost<Model>, 2, kSe3ParamSize, 3>(
        new ReprojectionCost<Model>(model, obs.pixel, obs.level));
    ceres::LossFunction* obs_loss = loss;
    if (obs.weight != 1.0) {
      scaled_losses.push_back(std::make_unique<ceres::ScaledLoss>(loss, obs.weight, ceres::DO_NOT_TAKE_OWNERSHIP));
      obs_loss = scaled_losses.back().get();
    }
    ceres_problem.AddResidualBlock(cost, obs_loss, blocks.poses[obs.keyframe].data(), blocks.points[obs.point].data());
    blocks.pose_used[obs.keyframe] = 1;
    blocks.point_used[obs.point] = 1;
  }
  for (const BaGroundObservation& g : problem.ground) {
    if (problem.keyframes[g.keyframe].fixed && problem.points[g.point].fixed) continue;
    auto* cost = new ceres::AutoDiffCostFunction<GroundHeightCost, 1, kSe3ParamSize, 3>(
        new GroundHeightCost(g.normal_c, g.height, g.sigma));
    scaled_losses.push_back(std::make_unique<ceres::ScaledLoss>(loss, g.weight, ceres::DO_NOT_TAKE_OWNERSHIP));
    ceres_problem.AddResidualBlock(cost, scaled_losses.back().get(), blocks.poses[g.keyframe].data(),
                                   blocks.points[g.point].data());
    blocks.pose_used[g.keyframe] = 1;
    blocks.point_used[g.point] = 1;
  }
}

ceres::LinearSolverType choose_linear_solver(const BundleAdjusterOptions& options, std::size_t free_keyframes,
                                             std::size_t free_points) {
  // Without free points there is nothing to eliminate: a small dense
  // problem over the poses.
  if (free_points == 0) return ceres::DENSE_NORMAL_CHOLESKY;
  switch (options.solver) {
    case BaLinearSolver::dense_schur: return ceres::DENSE_SCHUR;
    case BaLinearSolver::sparse_schur: return ceres::SPARSE_SCHUR;
    case BaLinearSolver::automatic: break;
  }
  return free_keyframes <= static_cast<std::size_t>(options.dense_schur_max_free_keyframes) ? ceres::DENSE_SCHUR
                                                                                            : ceres::SPARSE_SCHUR;
}

}  // namespace

BundleAdjuster::BundleAdjuster(BundleAdjusterOptions options) : options_(std::move(options)) {
  check_option(options_.max_iterations >= 0, "max_iterations must be >= 0");
  check_option(std::isfinite(options_.loss_scale) && options_.loss_scale > 0.0, "loss_scale must be finite and > 0");
  check_option(std::isfinite(options_.outlier_chi2) && options_.outlier_chi2 > 0.0,
               "outlier_chi2 must be finite and > 0");
  check_option(options_.num_threads >= 1, "num_threads must be >= 1");
  check_option(options_.dense_schur_max_free_keyframes >= 0, "dense_schur_max_free_keyframes must be >= 0");
  for (double tolerance : {options_.function_tolerance, options_.gradient_tolerance, options_.parameter_tolerance})
    check_option(std::isfinite(tolerance) && tolerance >= 0.0, "tolerances must be finite and >= 0");
}

BaResult BundleAdjuster::solve(BaProblem& problem, const Camera& camera) const {
  const Stopwatch start;
  validate_ba_problem(problem);

  BaResult result;
  const ErrorSummary initial = measure_errors(problem, camera, options_.outlier_chi2);
  result.initial_rms_px = initial.rms_px;
  auto finish_unchanged = [&](bool aborted) {
    result.aborted = aborted;
    result.converged = !aborted;
    result.final_rms_px = initial.rms_px;
    result.final_inlier_rms_px = initial.inlier_rms_px;
    result.outliers = initial.outliers;
    result.time_ms = start.elapsed_ms();
    return result;
  };
  if (options_.abort != nullptr && options_.abort->load(std::memory_order_acquire)) return finish_unchanged(true);

  ParameterBlocks blocks(problem);
  const std::unique_ptr<ceres::LossFunction> loss = make_loss(options_.loss, options_.loss_scale);
  std::vector<std::unique_ptr<ceres::LossFunction>> scaled_losses;  // per weighted observation
  SE3Manifold se3_manifold;
  std::unique_ptr<ceres::Manifold> anchor_manifold;

  ceres::Problem::Options problem_options;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem ceres_problem(problem_options);
  camera.visit(
      [&](const auto& model) { add_residuals(ceres_problem, problem, model, loss.get(), blocks, scaled_losses); });

  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
  for (std::size_t i = 0; i < problem.points.size(); ++i) {
    if (!blocks.point_used[i]) continue;
    double* block = blocks.points[i].data();
    ordering->AddElementToGroup(block, 0);  // points are eliminated first (Schur)
    if (problem.points[i].fixed)
      ceres_problem.SetParameterBlockConstant(block);
    else
      ++result.free_points;
  }
  for (std::size_t i = 0; i < problem.keyframes.size(); ++i) {
    if (!blocks.pose_used[i]) continue;
    double* block = blocks.poses[i].data();
    ordering->AddElementToGroup(block, 1);
    if (problem.keyframes[i].fixed) {
      ceres_problem.SetParameterBlockConstant(block);
      continue;
    }
    ++result.free_keyframes;
    if (problem.scale_anchor && problem.scale_anchor->keyframe == i) {
      const Eigen::Vector3d reference =
          problem.keyframes[problem.scale_anchor->reference].T_c_w.inverse().translation();
      const Eigen::Vector3d centre = problem.keyframes[i].T_c_w.inverse().translation();
      anchor_manifold = make_centre_distance_manifold(reference, (centre - reference).norm());
      ceres_problem.SetManifold(block, anchor_manifold.get());
    } else {
      ceres_problem.SetManifold(block, &se3_manifold);
    }
  }
  if (result.free_keyframes + result.free_points == 0) return finish_unchanged(false);

  AbortCallback callback(options_.abort, options_.on_iteration);
  ceres::Solver::Options solver_options;
  solver_options.minimizer_type = ceres::TRUST_REGION;
  solver_options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  solver_options.linear_solver_type = choose_linear_solver(options_, result.free_keyframes, result.free_points);
  if (solver_options.linear_solver_type == ceres::DENSE_SCHUR ||
      solver_options.linear_solver_type == ceres::SPARSE_SCHUR)
    solver_options.linear_solver_ordering = ordering;
  if (!ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::SUITE_SPARSE))
    solver_options.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
  solver_options.max_num_iterations = options_.max_iterations;
  solver_options.num_threads = options_.num_threads;
  solver_options.function_tolerance = options_.function_tolerance;
  solver_options.gradient_tolerance = options_.gradient_tolerance;
  solver_options.parameter_tolerance = options_.parameter_tolerance;
  solver_options.logging_type = ceres::SILENT;
  solver_options.minimizer_progress_to_stdout = false;
  solver_options.callbacks.push_back(&callback);

  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &ceres_problem, &summary);
  if (summary.termination_type == ceres::FAILURE)
    spdlog::warn("bundle adjustment: Ceres failed ({}); the problem is left as it was", summary.message);

  for (std::size_t i = 0; i < problem.keyframes.size(); ++i)
    if (blocks.pose_used[i] && !problem.keyframes[i].fixed)
      problem.keyframes[i].T_c_w = se3_from_params(blocks.poses[i].data());
  for (std::size_t i = 0; i < problem.points.size(); ++i)
    if (blocks.point_used[i] && !problem.points[i].fixed)
      problem.points[i].p_w = Eigen::Map<const Eigen::Vector3d>(blocks.points[i].data());

  const ErrorSummary final_errors = measure_errors(problem, camera, options_.outlier_chi2);
  result.aborted = callback.aborted();
  result.converged = !result.aborted && summary.termination_type == ceres::CONVERGENCE;
  // summary.iterations starts with iteration 0, the initial evaluation.
  result.iterations = summary.iterations.empty() ? 0 : static_cast<int>(summary.iterations.size()) - 1;
  result.final_rms_px = final_errors.rms_px;
  result.final_inlier_rms_px = final_errors.inlier_rms_px;
  result.outliers = final_errors.outliers;
  result.solver_report = summary.BriefReport();
  result.time_ms = start.elapsed_ms();
  spdlog::debug(
      "bundle adjustment: {} free keyframes, {} free points, {} observations, {} iterations, "
      "RMS {:.3f} -> {:.3f} px, {} outliers, {:.1f} ms{}",
      result.free_keyframes, result.free_points, problem.observations.size(), result.iterations, result.initial_rms_px,
      result.final_rms_px, result.outliers.size(), result.time_ms, result.aborted ? " (aborted)" : "");
  return result;
}

}  // namespace facadeslam
