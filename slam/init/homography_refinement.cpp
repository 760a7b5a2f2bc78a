#include "slam/init/homography_refinement.hpp"

#include <cmath>
#include <optional>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/QR>

#include "slam/init/robust_lm.hpp"

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

}  // namespace

Eigen::Matrix3d refine_homography(const Eigen::Matrix3d& H_in, const std::vector<Eigen::Vector2d>& x0,
                                  const std::vector<Eigen::Vector2d>& x1, const std::vector<int>& indices,
                                  double huber_px, int max_iterations) {
  Vector9 h = to_vector(H_in).normalized();
  if (indices.size() < 5 || !h.allFinite()) return from_vector(h);
  const auto count = static_cast<Eigen::Index>(indices.size());

  // Forward and backward transfer errors, four per match; none when H is
  // singular or sends a point to infinity.
  const auto residuals = [&](const Vector9& hv) -> std::optional<Eigen::VectorXd> {
    const Eigen::Matrix3d H = from_vector(hv);
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(H);
    if (!lu.isInvertible()) return std::nullopt;
    const Eigen::Matrix3d H_inv = lu.inverse();
    Eigen::VectorXd r(4 * count);
    for (Eigen::Index n = 0; n < count; ++n) {
      const auto i = static_cast<std::size_t>(indices[static_cast<std::size_t>(n)]);
      const Eigen::Vector3d f = H * x0[i].homogeneous(), b = H_inv * x1[i].homogeneous();
      if (std::abs(f.z()) < 1e-12 || std::abs(b.z()) < 1e-12) return std::nullopt;
      r.segment<2>(4 * n) = f.hnormalized() - x1[i];
      r.segment<2>(4 * n + 2) = b.hnormalized() - x0[i];
    }
    return r;
  };
  const auto retract = [](const Vector9& hv, const Vector8& delta) -> Vector9 {
    return (hv + tangent_basis(hv) * delta).normalized();
  };
  h = robust_lm::minimise<8>(h, huber_px, max_iterations, residuals, retract);
  return from_vector(h);
}

}  // namespace facadeslam
