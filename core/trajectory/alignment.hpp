#pragma once
// Least-squares similarity between two corresponding point sets (Umeyama 1991,
// "Least-squares estimation of transformation parameters between two point
// patterns"): finds s, R, t minimising sum |target_i - (s R source_i + t)|^2.
// Monocular SLAM has no metric scale, so its trajectories are compared with
// ground truth after a Sim(3) alignment; SE(3) alignment keeps s = 1.
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace facadeslam {

struct Sim3Alignment {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  double scale = 1.0;

  // s R p + t
  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return scale * (R * p) + t; }
  // A camera pose moved with its position: rotation R R_w_c, position
  // s R p + t. The camera's own axes are not scaled, so the result stays a
  // rigid pose (the scale shows in the distances between poses).
  Eigen::Isometry3d apply_to_pose(const Eigen::Isometry3d& T_w_c) const {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = R * T_w_c.linear();
    T.translation() = apply(T_w_c.translation());
    return T;
  }
};

// Aligns `source` onto `target` (same length, corresponding by index), so that
// target ≈ scale * R * source + t. With `with_scale` false the scale is 1.
// Throws Error when the problem has no unique answer: different lengths, fewer
// than 3 pairs, or points that are (nearly) all on one line or one point.
Sim3Alignment umeyama_alignment(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                                bool with_scale);

}  // namespace facadeslam
