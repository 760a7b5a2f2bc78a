#pragma once
// Non-linear refinement of a relative pose from its epipolar geometry.
// A RANSAC essential matrix comes from the best minimal (five-point) sample
// only, so its rotation can be off by a tenth of a degree or more; a few
// Levenberg-Marquardt steps on the Sampson distances of all inliers bring it
// down to the noise level before the points are triangulated.
#include <vector>

#include <Eigen/Core>

#include "core/lie/se3.hpp"

namespace facadeslam {

struct EssentialRefinementOptions {
  double focal_px = 1.0;  // converts normalised residuals to pixels (sqrt(fx fy))
  double huber_px = 1.0;  // Huber threshold on the Sampson distance, in pixels
  int max_iterations = 20;
};

// Sampson distance of one match (rays on the z = 1 plane) under E, in the
// normalised units of the rays.
double sampson_distance(const Eigen::Matrix3d& E, const Eigen::Vector3d& ray0, const Eigen::Vector3d& ray1);

// E = [t]x R of T_c1_c0 (x1^T E x0 = 0 for rays of a point in both cameras).
Eigen::Matrix3d essential_from_pose(const SE3d& T_c1_c0);

// Refines the rotation and the translation DIRECTION of T_c1_c0 (|t| is
// kept, it is unobservable) on the matches `indices` of rays0/rays1, by
// minimising Huber-weighted Sampson distances. Returns the input unchanged
// when |t| is zero or nothing improves.
SE3d refine_relative_pose(const SE3d& T_c1_c0, const std::vector<Eigen::Vector3d>& rays0,
                          const std::vector<Eigen::Vector3d>& rays1, const std::vector<int>& indices,
                          const EssentialRefinementOptions& options);

}  // namespace facadeslam
