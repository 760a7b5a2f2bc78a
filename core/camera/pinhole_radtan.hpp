#pragma once
// Pinhole camera with OpenCV's radial-tangential ("plumb bob") distortion,
// coefficient order k1 k2 p1 p2 k3 as in cv::projectPoints:
//   r2 = x^2 + y^2,  radial = 1 + k1 r2 + k2 r2^2 + k3 r2^3
//   xd = x radial + 2 p1 x y + p2 (r2 + 2 x^2)
//   yd = y radial + p1 (r2 + 2 y^2) + 2 p2 x y
//   u = fx xd + cx,  v = fy yd + cy
// Pixel (0,0) is the centre of the top-left pixel, the same convention as
// OpenCV, so K and the coefficients carry over unchanged.
//
// project() is templated on the scalar so that Ceres can auto-differentiate
// bundle adjustment through it (T = double or ceres::Jet). It does not check
// that the point is in front of the camera: callers test z > 0 first.
#include <Eigen/Core>

#include "core/camera/projection_chain.hpp"

namespace facadeslam {

struct PinholeRadTan {
  double fx = 1.0;  // focal lengths in pixels
  double fy = 1.0;
  double cx = 0.0;  // principal point in pixels
  double cy = 0.0;
  double k1 = 0.0;  // radial
  double k2 = 0.0;
  double p1 = 0.0;  // tangential
  double p2 = 0.0;
  double k3 = 0.0;  // radial, sixth order

  bool has_distortion() const { return k1 != 0.0 || k2 != 0.0 || p1 != 0.0 || p2 != 0.0 || k3 != 0.0; }

  // Normalised (z = 1 plane) coordinates -> distorted normalised coordinates.
  template <class T>
  Eigen::Matrix<T, 2, 1> distort(const Eigen::Matrix<T, 2, 1>& xn) const {
    const T x = xn(0), y = xn(1);
    const T xx = x * x, yy = y * y, xy = x * y;
    const T r2 = xx + yy;
    const T radial = T(1.0) + r2 * (k1 + r2 * (k2 + r2 * k3));
    return {x * radial + 2.0 * p1 * xy + p2 * (r2 + 2.0 * xx), y * radial + p1 * (r2 + 2.0 * yy) + 2.0 * p2 * xy};
  }

  // d distort / d xn.
  Eigen::Matrix2d distort_jacobian(const Eigen::Vector2d& xn) const;

  // Inverse of distort() by Newton iteration to full double precision (not
  // OpenCV's fixed five fixed-point steps, which leave errors of several
  // pixels at the corners of a strongly distorted image). Where the
  // distortion cannot be inverted (far outside the calibrated field, where
  // the polynomial folds back) it returns the closest point it reached.
  Eigen::Vector2d undistort(const Eigen::Vector2d& xd) const;

  // Camera-frame point -> pixel.
  template <class T>
  Eigen::Matrix<T, 2, 1> project(const Eigen::Matrix<T, 3, 1>& p_c) const {
    return projection_chain::project(*this, p_c);
  }

  // Pixel -> ray on the z = 1 plane.
  Eigen::Vector3d unproject(const Eigen::Vector2d& px) const { return projection_chain::unproject(*this, px); }

  // d project / d p_c, analytic.
  Eigen::Matrix<double, 2, 3> project_jacobian(const Eigen::Vector3d& p_c) const {
    return projection_chain::project_jacobian(*this, p_c);
  }
};

}  // namespace facadeslam
