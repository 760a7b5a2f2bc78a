#include "core/camera/atan_camera.hpp"

#include <limits>
#include <numbers>

namespace facadeslam {

namespace atan_detail {

double tan_half_ratio(double w) {
  // 2 tan(w/2) / w = 1 + w^2/12 + w^4/120 + O(w^6); below 1e-4 the next
  // term is under 1e-26, far below rounding.
  if (std::abs(w) < 1e-4) {
    const double w2 = w * w;
    return 1.0 + w2 * (1.0 / 12.0 + w2 / 120.0);
  }
  return 2.0 * std::tan(0.5 * w) / w;
}

namespace {

// d/du of atan(sqrt(u)) / sqrt(u). The closed form (1/(1+u) - g(u)) / (2u)
// cancels badly for small u, so there the series
// sum_{k>=1} (-1)^k k u^(k-1) / (2k+1) is used instead.
double atan_sqrt_ratio_derivative(double u) {
  if (u < kSeriesBound) {
    double sum = -9.0 / 19.0;
    for (int k = 8; k >= 1; --k) sum = (k % 2 == 0 ? 1.0 : -1.0) * k / (2.0 * k + 1.0) + u * sum;
    return sum;
  }
  return (1.0 / (1.0 + u) - atan_sqrt_ratio(u)) / (2.0 * u);
}

// tan(s) / s with its series near s = 0.
double tan_ratio(double s) {
  if (std::abs(s) < 1e-4) {
    const double s2 = s * s;
    return 1.0 + s2 * (1.0 / 3.0 + s2 * 2.0 / 15.0);
  }
  return std::tan(s) / s;
}

}  // namespace
}  // namespace atan_detail

Eigen::Matrix2d AtanCamera::distort_jacobian(const Eigen::Vector2d& xn) const {
  // x_d = F(q) x with q = |x|^2 and F(q) = R g(a^2 q), so
  // d x_d / d x = F I + 2 F'(q) x x^T.
  const double a = 2.0 * std::tan(0.5 * w);
  const double ratio = atan_detail::tan_half_ratio(w);
  const double u = a * a * xn.squaredNorm();
  const double F = ratio * atan_detail::atan_sqrt_ratio(u);
  const double dF_dq = ratio * a * a * atan_detail::atan_sqrt_ratio_derivative(u);
  return F * Eigen::Matrix2d::Identity() + 2.0 * dF_dq * xn * xn.transpose();
}

double AtanCamera::max_distorted_radius() const {
  return w > 0.0 ? 0.5 * std::numbers::pi / w : std::numeric_limits<double>::infinity();
}

Eigen::Vector2d AtanCamera::undistort(const Eigen::Vector2d& xd) const {
  const double rd = xd.norm();
  if (w == 0.0 || rd == 0.0) return xd;
  // r = tan(r_d w) / a, i.e. x = x_d (w / a) tan(s) / s with s = r_d w.
  const double s_max = 0.5 * std::numbers::pi - 1e-9;
  const double s = rd * w;
  if (s < s_max) return xd * (atan_detail::tan_ratio(s) / atan_detail::tan_half_ratio(w));
  const double a = 2.0 * std::tan(0.5 * w);
  return xd * (std::tan(s_max) / (a * rd));
}

}  // namespace facadeslam
