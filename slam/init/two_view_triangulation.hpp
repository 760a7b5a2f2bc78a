#pragma once
// Triangulation of two-view matches under a candidate relative pose, and the
// per-point checks that decide which points may seed the map: in front of
// both cameras, reprojecting within a few pixels in both REAL images (so lens
// distortion is accounted for exactly), and seen under enough parallax.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"

namespace facadeslam {

// Linear (DLT) triangulation from rays on the z = 1 plane of each camera
// (Camera::unproject), camera 0 at the origin and T_c1_c0 the second camera.
// Returns the point in camera 0's frame, or nothing when it lies at infinity
// (parallel rays).
std::optional<Eigen::Vector3d> triangulate_dlt(const SE3d& T_c1_c0, const Eigen::Vector3d& ray0,
                                               const Eigen::Vector3d& ray1);

// Angle in radians between the two viewing rays of p_c0: from camera 0's
// centre and from camera 1's centre.
double parallax_angle(const SE3d& T_c1_c0, const Eigen::Vector3d& p_c0);

// Matches as pixels and their rays, shared by every candidate pose.
struct TwoViewMatches {
  std::vector<Eigen::Vector2d> pixels0, pixels1;  // real (distorted) level-0 pixels
  std::vector<Eigen::Vector3d> rays0, rays1;      // Camera::unproject of the pixels
};

struct PointCheckOptions {
  double max_reprojection_error_px = 2.0;
  double min_parallax_rad = 0.0;
};

// The verdict of one candidate pose over a subset of the matches.
struct PoseEvaluation {
  // In front of both cameras with small reprojection errors (any parallax).
  std::vector<int> consistent;
  std::vector<double> consistent_parallax_rad;
  // Consistent and with enough parallax: these seed the map.
  std::vector<int> good;
  std::vector<Eigen::Vector3d> good_points_c0;
  double good_reprojection_error_sum = 0.0;  // sum over `good` of the larger of the two errors

  int good_count() const { return static_cast<int>(good.size()); }
  double median_parallax_rad() const;  // over `consistent` (0 when empty)
};

PoseEvaluation evaluate_pose(const Camera& camera, const SE3d& T_c1_c0, const TwoViewMatches& matches,
                             const std::vector<int>& indices, const PointCheckOptions& options);

}  // namespace facadeslam
