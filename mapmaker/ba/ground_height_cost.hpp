#pragma once
// The ground gauge's residual (BaGroundObservation): a point's height along
// the ground normal in its keyframe's camera frame against the camera's
// height above the ground, whitened by sigma:
//
//   r = (normal_c . (q * p_w + t) - height) / sigma
//
// Parameter blocks as ReprojectionCost's (pose 7 in the SE3Manifold layout,
// point 3, read as pose_block.hpp says), so the points are still eliminated
// first by the Schur solvers.
#include <Eigen/Core>

#include "mapmaker/ba/pose_block.hpp"

namespace facadeslam {

class GroundHeightCost {
 public:
  GroundHeightCost(const Eigen::Vector3d& normal_c, double height, double sigma)
      : normal_c_(normal_c), height_(height), inv_sigma_(1.0 / sigma) {}

  template <class T>
  bool operator()(const T* pose, const T* point, T* residual) const {
    const Eigen::Matrix<T, 3, 1> p_c = to_camera_frame(pose, point);
    residual[0] = (normal_c_.cast<T>().dot(p_c) - T(height_)) * T(inv_sigma_);
    return true;
  }

 private:
  Eigen::Vector3d normal_c_;
  double height_;
  double inv_sigma_;
};

}  // namespace facadeslam
