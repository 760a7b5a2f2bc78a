#pragma once
// A world point taken into the camera frame of a pose parameter block, for
// T = double or ceres::Jet (the bundle adjustment's residuals).
//
// The block is read in place (the SE3Manifold layout [qx qy qz qw tx ty tz],
// see core/lie/manifolds.hpp) rather than through se3_from_params(): that
// normalises the quaternion and builds SO3/SE3 objects, which with Jets made
// the residual + Jacobian evaluation 1.8x slower (bench/mapmaker/ba_bench.cpp,
// BM_ResidualJacobians). Normalising is unnecessary: the block starts as a
// unit quaternion and SE3Manifold::Plus writes unit quaternions, and on the
// unit sphere Eigen's rotation formula equals the normalised one, so its
// derivative along the manifold's tangent (all Ceres uses) is the same.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace facadeslam {

template <class T>
Eigen::Matrix<T, 3, 1> to_camera_frame(const T* pose, const T* point_w) {
  const Eigen::Map<const Eigen::Quaternion<T>> q(pose);
  const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t(pose + 4);
  const Eigen::Map<const Eigen::Matrix<T, 3, 1>> p_w(point_w);
  return q * p_w + t;
}

}  // namespace facadeslam
