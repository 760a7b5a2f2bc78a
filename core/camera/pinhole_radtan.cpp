#include "core/camera/pinhole_radtan.hpp"

#include <cmath>

#include <Eigen/LU>

namespace facadeslam {

Eigen::Matrix2d PinholeRadTan::distort_jacobian(const Eigen::Vector2d& xn) const {
  const double x = xn(0), y = xn(1);
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
  const double d_radial_d_r2 = k1 + r2 * (2.0 * k2 + 3.0 * k3 * r2);
  Eigen::Matrix2d J;
  J(0, 0) = radial + 2.0 * x * x * d_radial_d_r2 + 2.0 * p1 * y + 6.0 * p2 * x;
  J(0, 1) = 2.0 * x * y * d_radial_d_r2 + 2.0 * p1 * x + 2.0 * p2 * y;
  J(1, 0) = 2.0 * x * y * d_radial_d_r2 + 2.0 * p1 * x + 2.0 * p2 * y;
  J(1, 1) = radial + 2.0 * y * y * d_radial_d_r2 + 6.0 * p1 * y + 2.0 * p2 * x;
  return J;
}

Eigen::Vector2d PinholeRadTan::undistort(const Eigen::Vector2d& xd) const {
  if (!has_distortion()) return xd;
  // Newton on distort(x) - xd = 0, started at xd (distortion is a small
  // perturbation of the identity near the centre). Each step is halved
  // until the residual shrinks, so the iteration never walks away from a
  // solution it was approaching; it stops when no step improves any more,
  // which is at the rounding level of double precision.
  Eigen::Vector2d x = xd;
  Eigen::Vector2d residual = distort(x) - xd;
  double error = residual.squaredNorm();
  for (int iteration = 0; iteration < 100 && error > 0.0; ++iteration) {
    const Eigen::Matrix2d J = distort_jacobian(x);
    const double det = J.determinant();
    if (!(std::abs(det) > 1e-300)) break;
    Eigen::Vector2d step = J.inverse() * residual;
    bool improved = false;
    for (int halving = 0; halving < 30; ++halving) {
      const Eigen::Vector2d candidate = x - step;
      const Eigen::Vector2d candidate_residual = distort(candidate) - xd;
      const double candidate_error = candidate_residual.squaredNorm();
      if (candidate_error < error) {
        x = candidate;
        residual = candidate_residual;
        error = candidate_error;
        improved = true;
        break;
      }
      step *= 0.5;
    }
    if (!improved) break;
  }
  return x;
}

}  // namespace facadeslam
