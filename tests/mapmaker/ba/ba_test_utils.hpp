#pragma once
// Shared pieces of the bundle adjustment tests: cameras, pose error measures,
// and the scale-anchor preparation of a perturbed street scene.
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"
#include "mapmaker/ba/ba_problem.hpp"

namespace facadeslam::test {

// A VGA pinhole camera with mild barrel distortion (exercises distort()).
inline Camera pinhole_camera() {
  PinholeRadTan model;
  model.fx = 500.0;
  model.fy = 505.0;
  model.cx = 319.5;
  model.cy = 239.5;
  model.k1 = -0.08;
  model.k2 = 0.01;
  model.p1 = 0.0005;
  model.p2 = -0.0003;
  return Camera(640, 480, model);
}

// PTAM's ATAN model with a wide-angle-like w.
inline Camera atan_camera() {
  AtanCamera model;
  model.fx = 480.0;
  model.fy = 480.0;
  model.cx = 319.5;
  model.cy = 239.5;
  model.w = 0.9;
  return Camera(640, 480, model);
}

inline Eigen::Vector3d centre_of(const SE3d& T_c_w) { return T_c_w.inverse().translation(); }

// Angle (rad) of the rotation between two poses.
inline double rotation_error(const SE3d& a, const SE3d& b) { return (a.so3() * b.so3().inverse()).log().norm(); }

// Distance between the camera centres of two poses.
inline double centre_error(const SE3d& a, const SE3d& b) { return (centre_of(a) - centre_of(b)).norm(); }

struct PoseErrors {
  double max_rotation = 0.0;  // rad
  double max_centre = 0.0;    // world units
};

inline PoseErrors pose_errors(const BaProblem& problem, const std::vector<SE3d>& reference) {
  PoseErrors e;
  for (std::size_t i = 0; i < problem.keyframes.size(); ++i) {
    e.max_rotation = std::max(e.max_rotation, rotation_error(problem.keyframes[i].T_c_w, reference[i]));
    e.max_centre = std::max(e.max_centre, centre_error(problem.keyframes[i].T_c_w, reference[i]));
  }
  return e;
}

inline std::vector<SE3d> poses_of(const BaProblem& problem) {
  std::vector<SE3d> poses;
  for (const BaKeyFrame& kf : problem.keyframes) poses.push_back(kf.T_c_w);
  return poses;
}

inline double max_point_error(const BaProblem& problem, const std::vector<Eigen::Vector3d>& reference) {
  double e = 0.0;
  for (std::size_t i = 0; i < problem.points.size(); ++i)
    e = std::max(e, (problem.points[i].p_w - reference[i]).norm());
  return e;
}

// Fixes keyframe 0 (left at its true pose: fix it before perturbing) and
// anchors the LAST keyframe's distance to it (the recommended global-BA
// gauge; the longest baseline pins the scale best), first moving that
// keyframe's centre back onto the true distance so that the solution can
// coincide with the truth.
inline void fix_gauge_with_anchor(BaProblem& problem, const std::vector<SE3d>& true_T_c_w) {
  const std::size_t last = problem.keyframes.size() - 1;
  problem.keyframes[0].fixed = true;
  const Eigen::Vector3d c0 = centre_of(problem.keyframes[0].T_c_w);
  const double true_distance = (centre_of(true_T_c_w[last]) - centre_of(true_T_c_w[0])).norm();
  SE3d& pose = problem.keyframes[last].T_c_w;
  const Eigen::Vector3d c = centre_of(pose);
  const Eigen::Vector3d c_on_sphere = c0 + (c - c0).normalized() * true_distance;
  pose = SE3d(pose.so3(), -(pose.so3() * c_on_sphere));
  problem.scale_anchor = BaScaleAnchor{last, 0};
}

}  // namespace facadeslam::test
