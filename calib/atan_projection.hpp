#pragma once
// PTAM's ATAN (FOV) projection with the INTRINSICS as template scalars, so
// that Ceres can differentiate with respect to fx, fy, cx, cy and w.
// core/camera's AtanCamera::project<T> takes only the point as a Jet (its
// parameters are doubles), which serves bundle adjustment but not
// calibration. The formula is the same (see core/camera/atan_camera.hpp):
//   r_d = atan(2 r tan(w/2)) / w,  x_d = x r_d / r,  pixel = (fx x_d + cx, fy y_d + cy)
// and the tests check that both agree to rounding.
#include <cmath>

#include <Eigen/Core>

#include "core/camera/atan_camera.hpp"

namespace facadeslam::calib {

// Layout of the intrinsics parameter block.
inline constexpr int kAtanFx = 0, kAtanFy = 1, kAtanCx = 2, kAtanCy = 3, kAtanW = 4;
inline constexpr int kAtanIntrinsicCount = 5;

// 2 tan(w/2) / w with its Taylor series near w = 0, where the quotient is
// 0/0 (the same as atan_detail::tan_half_ratio, for any scalar type).
template <class T>
T atan_tan_half_ratio(const T& w) {
  using std::abs;
  using std::tan;
  if (abs(w) < 1e-4) {
    const T w2 = w * w;
    return T(1.0) + w2 * (1.0 / 12.0 + w2 / 120.0);
  }
  return 2.0 * tan(0.5 * w) / w;
}

// `intrinsics` = [fx, fy, cx, cy, w]; with `tie_focal` fy is ignored and fx
// used for both axes (a fixed aspect ratio of 1).
template <class T>
Eigen::Matrix<T, 2, 1> atan_project(const T* intrinsics, const Eigen::Matrix<T, 3, 1>& p_c, bool tie_focal) {
  using std::tan;
  const T& w = intrinsics[kAtanW];
  const T xn = p_c(0) / p_c(2);
  const T yn = p_c(1) / p_c(2);
  const T a = 2.0 * tan(0.5 * w);
  const T u = a * a * (xn * xn + yn * yn);
  const T factor = atan_tan_half_ratio(w) * atan_detail::atan_sqrt_ratio(u);
  const T& fx = intrinsics[kAtanFx];
  const T& fy = tie_focal ? intrinsics[kAtanFx] : intrinsics[kAtanFy];
  return {fx * (xn * factor) + intrinsics[kAtanCx], fy * (yn * factor) + intrinsics[kAtanCy]};
}

}  // namespace facadeslam::calib
