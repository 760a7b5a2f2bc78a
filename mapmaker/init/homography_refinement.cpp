#include "mapmaker/init/homography_refinement.hpp"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/QR>

namespace facadeslam {
namespace {

using Vector8 = Eigen::Matrix<double, 8, 1>;
using Vector9 = Eigen::Matrix<double, 9, 1>;

Eigen::Matrix3d from_vector(const Vector9& h) { return Eigen::Map<const Eigen::Matrix3d>(h.data()); }
Vector9 to_vector(const Eigen::Matrix3d& H) { return Eigen::Map<const Vector9>(H.data()); }

// Eight unit vectors orthogonal to h: H moves as normalise(h + B delta).
Eigen::Matrix<double, 9, 8> tangent_basis(const Vector9& h) {
  const Eigen::HouseholderQR<Vector9> qr(h);
  const Eigen::Matrix<double, 9, 9> Q = qr.householderQ();
  return Q.rightCols<8>();
}

double huber_cost(double r, double k) {
  const double a = std::abs(r);
  return a <= k ? r * r : 2.0 * k * a - k * k;
}

}  // namespace

Eigen::Matrix3d refine_homography(const Eigen::Matrix3d& H_in, const std::vector<Eigen::Vector2d>& x0,
                                  const std::vector<Eigen::Vector2d>& x1, const std::vector<int>& indices,
                                  double huber_px, int max_iterations) {
  Vector9 h = to_vector(H_in).normalized();
  if (indices.size() < 5 || !h.allFinite()) return from_vector(h);
  const auto count = static_cast<Eigen::Index>(indices.size());

  // Forward and backward transfer errors, four per match; empty when H is
  // singular or sends a point to infinity.
  const auto residuals = [&](const Vector9& hv, Eigen::VectorXd& r) {
    const Eigen::Matrix3d H = from_vector(hv);
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(H);
    if (!lu.isInvertible()) return false;
    const Eigen::Matrix3d H_inv = lu.inverse();
    r.resize(4 * count);
    for (Eigen::Index n = 0; n < count; ++n) {
      const auto i = static_cast<std::size_t>(indices[static_cast<std::size_t>(n)]);
      const Eigen::Vector3d f = H * x0[i].homogeneous(), b = H_inv * x1[i].homogeneous();
      if (std::abs(f.z()) < 1e-12 || std::abs(b.z()) < 1e-12) return false;
      r.segment<2>(4 * n) = f.hnormalized() - x1[i];
      r.segment<2>(4 * n + 2) = b.hnormalized() - x0[i];
    }
    return true;
  };
  const auto cost = [&](const Eigen::VectorXd& r) {
    double c = 0.0;
    for (Eigen::Index n = 0; n < r.size(); ++n) c += huber_cost(r(n), huber_px);
    return c;
  };

  Eigen::VectorXd r, r_plus, r_minus, r_candidate;
  if (!residuals(h, r)) return from_vector(h);
  double current = cost(r);
  double lambda = 1e-4;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    const Eigen::Matrix<double, 9, 8> B = tangent_basis(h);
    Eigen::MatrixXd J(r.size(), 8);
    constexpr double step = 1e-7;
    bool jacobian_ok = true;
    for (int p = 0; p < 8 && jacobian_ok; ++p) {
      jacobian_ok = residuals((h + step * B.col(p)).normalized(), r_plus) &&
                    residuals((h - step * B.col(p)).normalized(), r_minus);
      if (jacobian_ok) J.col(p) = (r_plus - r_minus) / (2.0 * step);
    }
    if (!jacobian_ok) break;
    Eigen::VectorXd w(r.size());
    for (Eigen::Index n = 0; n < r.size(); ++n) w(n) = std::abs(r(n)) <= huber_px ? 1.0 : huber_px / std::abs(r(n));
    const Eigen::Matrix<double, 8, 8> A = J.transpose() * w.asDiagonal() * J;
    const Vector8 g = J.transpose() * w.asDiagonal() * r;

    bool improved = false;
    while (lambda < 1e8) {
      Eigen::Matrix<double, 8, 8> damped = A;
      damped.diagonal() += lambda * A.diagonal().cwiseMax(1e-12);
      const Vector8 delta = damped.ldlt().solve(-g);
      if (!delta.allFinite()) break;
      const Vector9 candidate = (h + B * delta).normalized();
      if (residuals(candidate, r_candidate)) {
        const double c = cost(r_candidate);
        if (c < current) {
          const bool converged = delta.norm() < 1e-12 || (current - c) < 1e-12 * current;
          h = candidate;
          r = r_candidate;
          current = c;
          lambda = std::max(lambda * 0.1, 1e-10);
          improved = !converged;
          break;
        }
      }
      lambda *= 10.0;
    }
    if (!improved) break;
  }
  return from_vector(h);
}

}  // namespace facadeslam
