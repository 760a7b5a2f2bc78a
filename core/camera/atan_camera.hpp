#pragma once
// PTAM's ATAN camera: the FOV distortion model of Devernay & Faugeras
// ("Straight lines have to be straight", 2001). With x the normalised
// (z = 1 plane) coordinates and r = |x|, the distorted radius is
//   r_d = atan(2 r tan(w/2)) / w,      inverse  r = tan(r_d w) / (2 tan(w/2)),
// and the pixel is (fx x_d + cx, fy y_d + cy) with x_d = x r_d / r.
// w = 0 is a plain pinhole camera; the limits w -> 0 and r -> 0 are handled
// with Taylor series, so the model is smooth (and auto-differentiable) there.
//
// Units differ from PTAM's camera.cfg on purpose: fx, fy, cx, cy are in
// PIXELS here, whereas PTAM stores them divided by the image width/height.
// A PTAM vector (fx', fy', cx', cy', w) for a W x H image converts as
// fx = fx' W, fy = fy' H, cx = cx' W - 0.5, cy = cy' H - 0.5 (PTAM measures
// cx', cy' across the image area, whose left/top edge lies at pixel -0.5
// when pixel (0,0) is the centre of the top-left pixel, as here).
//
// project() is templated on the scalar for Ceres auto-differentiation
// (T = double or ceres::Jet); it does not check that z > 0.
#include <cmath>

#include <Eigen/Core>

#include "core/camera/projection_chain.hpp"

namespace facadeslam {

namespace atan_detail {

// atan(sqrt(u)) / sqrt(u) for u >= 0. Below kSeriesBound the alternating
// series sum_k (-1)^k u^k / (2k+1) is used, so u = 0 is fine and a Jet never
// meets the infinite derivative of sqrt at 0. Ten terms leave a truncation
// error under 1e-20 there.
inline constexpr double kSeriesBound = 1e-2;

template <class T>
T atan_sqrt_ratio(const T& u) {
  using std::atan;
  using std::sqrt;
  if (u < kSeriesBound) {
    // Horner's scheme for 1 - u/3 + u^2/5 - ... - u^9/19.
    T sum(-1.0 / 19.0);
    for (int k = 8; k >= 0; --k) sum = (k % 2 == 0 ? 1.0 : -1.0) / (2.0 * k + 1.0) + u * sum;
    return sum;
  }
  const T s = sqrt(u);
  return atan(s) / s;
}

// 2 tan(w/2) / w, the slope of r_d(r) at r = 0, with its Taylor series near
// w = 0 (where 0/0 would appear).
double tan_half_ratio(double w);

}  // namespace atan_detail

struct AtanCamera {
  double fx = 1.0;  // focal lengths in pixels
  double fy = 1.0;
  double cx = 0.0;  // principal point in pixels
  double cy = 0.0;
  double w = 0.0;  // FOV distortion parameter in radians, [0, pi)

  // Normalised coordinates -> distorted normalised coordinates.
  template <class T>
  Eigen::Matrix<T, 2, 1> distort(const Eigen::Matrix<T, 2, 1>& xn) const {
    const double a = 2.0 * std::tan(0.5 * w);
    const T u = a * a * (xn(0) * xn(0) + xn(1) * xn(1));
    const T factor = atan_detail::tan_half_ratio(w) * atan_detail::atan_sqrt_ratio(u);
    return {xn(0) * factor, xn(1) * factor};
  }

  Eigen::Matrix2d distort_jacobian(const Eigen::Vector2d& xn) const;

  // Closed-form inverse of distort(). Distorted radii with r_d w >= pi/2 lie
  // beyond the model's field (their ray would be at or behind 90 degrees);
  // they are clamped just inside it, giving a very long but finite ray.
  Eigen::Vector2d undistort(const Eigen::Vector2d& xd) const;

  // The largest distorted normalised radius that undistort() can invert
  // (pi / (2 w)), or infinity for w = 0.
  double max_distorted_radius() const;

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
