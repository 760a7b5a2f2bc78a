#pragma once
// The chain both camera models share: a camera-frame point is normalised onto
// the z = 1 plane, distorted by the model, then mapped to pixels by the
// linear intrinsics (fx, fy, cx, cy). A model supplies distort(),
// distort_jacobian() and undistort(); the chain, its inverse and its
// Jacobian live here once.
#include <Eigen/Core>

namespace facadeslam::projection_chain {

// Camera-frame point -> pixel; templated for Ceres auto-differentiation.
template <class Model, class T>
Eigen::Matrix<T, 2, 1> project(const Model& m, const Eigen::Matrix<T, 3, 1>& p_c) {
  const Eigen::Matrix<T, 2, 1> xn(p_c(0) / p_c(2), p_c(1) / p_c(2));
  const Eigen::Matrix<T, 2, 1> xd = m.distort(xn);
  return {m.fx * xd(0) + m.cx, m.fy * xd(1) + m.cy};
}

// Pixel -> ray on the z = 1 plane.
template <class Model>
Eigen::Vector3d unproject(const Model& m, const Eigen::Vector2d& px) {
  const Eigen::Vector2d xd((px(0) - m.cx) / m.fx, (px(1) - m.cy) / m.fy);
  const Eigen::Vector2d xn = m.undistort(xd);
  return {xn(0), xn(1), 1.0};
}

// d project / d p_c = K * d distort / d xn * d xn / d p_c.
template <class Model>
Eigen::Matrix<double, 2, 3> project_jacobian(const Model& m, const Eigen::Vector3d& p_c) {
  const double inv_z = 1.0 / p_c(2);
  const Eigen::Vector2d xn(p_c(0) * inv_z, p_c(1) * inv_z);
  Eigen::Matrix<double, 2, 3> d_xn_d_p;
  d_xn_d_p << inv_z, 0.0, -xn(0) * inv_z,  //
      0.0, inv_z, -xn(1) * inv_z;
  const Eigen::Matrix2d d_px_d_xd = Eigen::Vector2d(m.fx, m.fy).asDiagonal();
  return d_px_d_xd * m.distort_jacobian(xn) * d_xn_d_p;
}

}  // namespace facadeslam::projection_chain
