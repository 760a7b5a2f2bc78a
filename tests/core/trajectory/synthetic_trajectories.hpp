#pragma once
// Trajectories with known properties for the evaluator tests.
#include <cmath>

#include <Eigen/Geometry>

#include "core/trajectory/trajectory.hpp"

namespace facadeslam::test {

// A rising helix, the camera yawing with the motion and nodding a little, so
// that positions span 3D and rotations vary about every axis.
inline Trajectory helix(std::size_t count, double dt = 0.1, double t0 = 1305031098.6659) {
  Trajectory trajectory;
  for (std::size_t i = 0; i < count; ++i) {
    const double a = 0.15 * static_cast<double>(i);
    StampedPose pose;
    pose.timestamp = t0 + dt * static_cast<double>(i);
    pose.T_w_c.translation() = Eigen::Vector3d(2.0 * std::cos(a), 2.0 * std::sin(a), 0.05 * static_cast<double>(i));
    pose.T_w_c.linear() = (Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()) *
                           Eigen::AngleAxisd(0.2 * std::sin(3 * a), Eigen::Vector3d::UnitX()) *
                           Eigen::AngleAxisd(0.1 * std::cos(2 * a), Eigen::Vector3d::UnitY()))
                              .toRotationMatrix();
    trajectory.push_back(pose);
  }
  return trajectory;
}

// A similarity transform applied to a whole trajectory (in the world frame).
struct Similarity {
  double scale = 1.0;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

inline Trajectory transformed(const Trajectory& trajectory, const Similarity& s) {
  Trajectory out = trajectory;
  for (auto& pose : out) {
    pose.T_w_c.translation() = s.scale * (s.R * pose.T_w_c.translation()) + s.t;
    pose.T_w_c.linear() = s.R * pose.T_w_c.linear();
  }
  return out;
}

inline Eigen::Matrix3d some_rotation() {
  return (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace facadeslam::test
