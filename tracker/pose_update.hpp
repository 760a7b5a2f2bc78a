#pragma once
// Robust Gauss-Newton refinement of the camera pose from 2D-3D matches (the
// tracker's pose update, PTAM's Tracker::CalcPoseUpdate iterated).
//
// Model: a measurement is a world point p_w found at level-0 pixel z while
// searching at pyramid level l. Its residual, in units of that level's pixels
// (PTAM: measurement noise of one pixel at the level searched), is
//     r = (z - pi(T_c_w p_w)) / 2^l,
// and with the LEFT update T_c_w <- exp(delta) T_c_w, delta = [rho, omega],
//     d pi(exp(delta) T p) / d delta = J_pi(p_c) [I, -hat(p_c)],  p_c = T p.
// Each iteration re-projects all points, re-estimates the robust scale from
// the median squared residual (tukey.hpp), weights every measurement with
// Tukey's biweight, and solves the 6x6 weighted normal equations. It stops
// after max_iterations or when |delta| < convergence.
//
// The returned weights, inlier flags, RMS and information matrix are
// evaluated at the returned pose. Information = sum w J^T J in the scaled
// units above (unit noise per level pixel); covariance is its inverse
// (multiply by sigma_squared for the empirical noise level).
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"
#include "tracker/tukey.hpp"

namespace facadeslam {

struct PoseMeasurement {
  Eigen::Vector3d p_w{0, 0, 0};
  Eigen::Vector2d pixel{0, 0};  // found position, level-0 pixels
  int level = 0;                // pyramid level it was searched at
  double weight = 1.0;          // prior weight, multiplies the Tukey weight (label-aware tracking)
};

struct PoseUpdateOptions {
  int max_iterations = 10;         // PTAM: 10 per stage
  double convergence = 1e-6;       // stop when |delta| falls below this
  double min_sigma_squared = 0.4;  // floor of the robust scale, level-pixels^2
  double tukey_c = kTukeyC;        // cut at c * sigma
  double median_to_sigma_squared = kMedianToSigmaSquared2d;
  double min_depth = 1e-6;  // points closer than this (or behind) are ignored
};

using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct PoseUpdateResult {
  SE3d T_c_w;
  std::vector<double> weights;        // Tukey weight per measurement (0 = outlier / behind camera)
  std::vector<std::uint8_t> inliers;  // weight > 0
  int num_inliers = 0;
  double inlier_rms_px = 0.0;  // RMS level-0 reprojection error of the inliers
  double sigma_squared = 0.0;  // robust scale at the final pose, level-pixels^2
  Matrix6d information = Matrix6d::Zero();
  Matrix6d covariance = Matrix6d::Zero();  // zero when the information is singular
  int iterations = 0;                      // Gauss-Newton steps taken
  bool converged = false;                  // |delta| < convergence was reached
  bool ok = false;                         // false: too few usable measurements, pose unchanged
};

// d pi(exp(delta) T_c_w p_w) / d delta at delta = 0, in level-0 pixels.
Eigen::Matrix<double, 2, 6> pose_measurement_jacobian(const SE3d& T_c_w, const Eigen::Vector3d& p_w,
                                                      const Camera& camera);

// Throws Error when a measurement's level is outside 0..3.
PoseUpdateResult update_pose(const SE3d& T_c_w, std::span<const PoseMeasurement> measurements, const Camera& camera,
                             const PoseUpdateOptions& options = {});

}  // namespace facadeslam
