#pragma once
// Local and global bundle adjustment with Ceres: keyframe poses on the SE3
// manifold (core/lie/manifolds.hpp, left updates), points in R^3, one
// auto-differentiated reprojection residual per observation through the
// concrete camera model (reprojection_cost.hpp), a robust loss, Schur
// elimination of the points.
//
// Usage by the map maker: copy the keyframes/points chosen by
// local_ba_selection / global_ba_selection (ba_selection.hpp) into a
// BaProblem, marking the fixed ones; solve without holding the map lock;
// write the poses and positions back under the lock; drop the measurements
// listed in BaResult::outliers.
//
// Gauge: the caller fixes the first keyframe. For a global BA, where that is
// the only fixed keyframe, set BaProblem::scale_anchor to keep the second
// keyframe's distance from the first. Recommended: it is exactly one
// constraint, so nothing observable is frozen (the optimum is the same map up
// to scale whichever keyframe is anchored), and the scale the initialiser
// chose then stays put from one global BA to the next instead of drifting
// along the unobservable direction. A local BA gets its scale from its fixed
// neighbours (local_ba_selection never frees the first keyframe).
//
// Determinism: with num_threads = 1 the result is a pure function of the
// input (bit for bit), as the --sync regression mode requires (tested). With
// more threads Ceres adds residual blocks and Schur complement contributions
// in the order its threads finish them, so results differ in the last bits
// from run to run (seen in 4 of 4 repeated two-thread solves of a 30-keyframe
// street; the tests check that they agree with one thread to round-off).
#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/camera/camera.hpp"
#include "mapmaker/ba/ba_problem.hpp"

namespace facadeslam {

// Robust losses on the whitened squared residual s = |r|^2 (Ceres' losses,
// a = loss_scale). Measured on the street tests (0.5 px noise, 5 % of the
// observations moved by 20 px, start 0.05 rad / 0.1 m off): cauchy stays as
// accurate as without outliers and reports 98 % of them with few false
// alarms; huber still lets them pull (pose errors ~2x); tukey is as good as
// cauchy but only from a start within about a pixel (it ignores every
// residual beyond a, so a poor start freezes), and wants a ~ 4.7.
enum class BaLoss {
  none,    // plain least squares
  huber,   // quadratic up to a, then linear
  cauchy,  // a^2 log(1 + s / a^2): influence falls off as 1/r (the default)
  tukey,   // biweight: zero influence beyond a
};

enum class BaLinearSolver {
  automatic,  // dense_schur up to dense_schur_max_free_keyframes, else sparse_schur
  dense_schur,
  sparse_schur,  // SuiteSparse (Eigen's sparse Cholesky if Ceres lacks it)
};

struct BundleAdjusterOptions {
  int max_iterations = 20;  // Levenberg–Marquardt iterations, >= 0
  BaLoss loss = BaLoss::cauchy;
  // The loss's scale in whitened units (multiples of the observation's
  // sigma = 2^level px): residual norms up to about this are inliers.
  // Default sqrt(5.991), the 95 % chi-square bound for 2 dof.
  double loss_scale = 2.447651;
  BaLinearSolver solver = BaLinearSolver::automatic;
  // With `automatic`: the largest number of free keyframes solved with
  // DENSE_SCHUR. Measured (bench/mapmaker/ba_bench.cpp, instruction counts
  // under callgrind, 10 iterations): dense does 1-3 % less work than sparse
  // for 5, 20, 50 and still 100 free keyframes, the reduced system's solve
  // being a small part of the iteration next to the residuals and the
  // elimination; beyond ~100 its cubic cost takes over, and SuiteSparse
  // exploits the street-like banded camera graph.
  int dense_schur_max_free_keyframes = 100;
  int num_threads = 1;  // Ceres threads; 1 gives bit-for-bit reproducible results
  // Polled after every iteration (and before the solve starts): when it reads
  // true the solve stops, keeping the last accepted iterate, and the result
  // says aborted. The map maker sets it when a new keyframe arrives.
  std::atomic<bool>* abort = nullptr;
  // An observation is an outlier when its whitened squared error after the
  // solve exceeds this (5.991: 95 % for 2 dof at sigma = 2^level px), or when
  // its point is behind the camera.
  double outlier_chi2 = 5.991;
  // Ceres convergence tolerances (see ceres::Solver::Options).
  double function_tolerance = 1e-6;
  double gradient_tolerance = 1e-10;
  double parameter_tolerance = 1e-8;
  // Diagnostics / tests: called after every iteration with its number
  // (0 = the initial evaluation), before the abort flag is read.
  std::function<void(int iteration)> on_iteration;
};

struct BaResult {
  bool converged = false;       // a Ceres tolerance was met (not: ran out of iterations, aborted)
  bool aborted = false;         // stopped by the abort flag
  int iterations = 0;           // Levenberg–Marquardt iterations run (accepted or not)
  double initial_rms_px = 0.0;  // sqrt(mean |project - pixel|^2) over all observations, level-0 px
  double final_rms_px = 0.0;
  double final_inlier_rms_px = 0.0;   // the same over the observations not reported as outliers
  double time_ms = 0.0;               // wall time of solve(), including problem set-up
  std::vector<std::size_t> outliers;  // indices into BaProblem::observations, ascending
  std::size_t free_keyframes = 0;     // blocks optimised (taking part and not fixed)
  std::size_t free_points = 0;
  std::string solver_report;  // Ceres' one-line summary
};

class BundleAdjuster {
 public:
  // Throws Error for an invalid option (max_iterations < 0, loss_scale or
  // outlier_chi2 not finite and > 0, num_threads < 1,
  // dense_schur_max_free_keyframes < 0, negative or non-finite tolerances).
  explicit BundleAdjuster(BundleAdjusterOptions options = {});

  const BundleAdjusterOptions& options() const { return options_; }

  // Adjusts the free poses and points of `problem` in place (also when the
  // solve is aborted or runs out of iterations: the last accepted iterate,
  // never worse in robust cost than the input). Throws Error for an invalid
  // problem (validate_ba_problem). Keyframes and points that appear in no
  // observation are left untouched.
  BaResult solve(BaProblem& problem, const Camera& camera) const;

 private:
  BundleAdjusterOptions options_;
};

}  // namespace facadeslam
