#pragma once
// ORB-SLAM-style scores of the two competing two-view models (Mur-Artal et
// al. 2015, section IV), so that the homography and the essential matrix are
// compared on the same matches with the same yardstick:
//   S_M = sum over matches and both directions of (T_H - e^2 / sigma^2) where
//   that chi-square value stays under the model's cut-off T_M,
// with e the symmetric transfer error for a homography (2 dof, T = 5.991) and
// the point-to-epipolar-line distance for a fundamental matrix (1 dof,
// T = 3.841). Both scores use the homography's T_H = 5.991 as the base, so a
// match explained equally well by both models scores about the same under
// each. A match is an inlier when both of its directions pass.
//
// Coordinates are "ideal" pixels: undistorted pixels of the pinhole camera
// with the real camera's fx, fy, cx, cy, so errors are in pixels.
#include <vector>

#include <Eigen/Core>

namespace facadeslam {

inline constexpr double kChiSquare95OneDof = 3.841;
inline constexpr double kChiSquare95TwoDof = 5.991;

struct ModelScore {
  double score = 0.0;
  std::vector<bool> inliers;
  int inlier_count = 0;
};

// H maps ideal pixels of view 0 to view 1 (x1 ~ H x0). A singular H scores 0.
ModelScore score_homography(const Eigen::Matrix3d& H, const std::vector<Eigen::Vector2d>& ideal0,
                            const std::vector<Eigen::Vector2d>& ideal1, double sigma_px);

// F satisfies x1^T F x0 = 0 for ideal pixels.
ModelScore score_fundamental(const Eigen::Matrix3d& F, const std::vector<Eigen::Vector2d>& ideal0,
                             const std::vector<Eigen::Vector2d>& ideal1, double sigma_px);

}  // namespace facadeslam
