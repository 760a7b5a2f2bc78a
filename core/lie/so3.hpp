#pragma once
// SO3<T>: 3D rotations stored as a unit quaternion, templated on the scalar so
// that Ceres can auto-differentiate through every operation (T = ceres::Jet).
//
// Conventions (shared with SE3 and Sim3):
//  * The tangent vector omega is an axis-angle vector: exp(omega) rotates by
//    |omega| radians about omega / |omega| (right-handed).
//  * hat(omega) is the skew matrix with hat(omega) p = omega x p.
//  * log returns |omega| <= pi; exp(log(R)) == R for every rotation.
//  * Left Jacobian:  exp(omega + d) ~= exp(J_l(omega) d) exp(omega);
//    right Jacobian: exp(omega + d) ~= exp(omega) exp(J_r(omega) d),
//    to first order in d.
//  * The quaternion is kept unit (every constructor normalises) and its sign
//    is not canonicalised: q and -q are the same rotation.
//  * The public constructors reject invalid input (zero or non-finite) with
//    std::invalid_argument. Operations never throw, and
//    from_quaternion_unchecked() is the non-throwing path for solver inner
//    loops (Ceres cost functors), where invalid numbers must flow on as NaN
//    for the solver to reject the step instead of aborting the solve.
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "core/lie/lie_coefficients.hpp"

namespace facadeslam {

template <class T>
class SO3 {
 public:
  using Scalar = T;
  using Vector3 = Eigen::Matrix<T, 3, 1>;
  using Matrix3 = Eigen::Matrix<T, 3, 3>;
  using Quaternion = Eigen::Quaternion<T>;
  using Tangent = Vector3;
  static constexpr int kDof = 3;

  // The identity rotation.
  SO3() : q_(Quaternion::Identity()) {}

  // From any non-zero quaternion, normalised. Throws std::invalid_argument
  // for a zero or non-finite quaternion.
  explicit SO3(const Quaternion& q) : q_(checked_normalised(q)) {}

  // From any quaternion, normalised without checks: a zero or non-finite
  // quaternion gives NaN or infinite entries instead of an exception.
  static SO3 from_quaternion_unchecked(const Quaternion& q) { return SO3(normalised(q), UnitTag{}); }

  // From a 3x3 matrix, projected onto the nearest rotation (Frobenius norm,
  // via SVD: R = U diag(1, 1, det(U V^T)) V^T) so that a slightly
  // non-orthonormal input (accumulated round-off, a solver's output) gives a
  // proper rotation. Throws std::invalid_argument for a non-finite matrix.
  // For non-floating-point scalars (ceres::Jet) the SVD iteration would not
  // carry derivatives reliably (it skips rotations on exactly diagonal
  // input), so the matrix goes through Eigen's quaternion conversion and a
  // normalisation instead: exact for rotation matrices, with the right
  // derivatives along rotations.
  explicit SO3(const Matrix3& m) : q_(checked_normalised(Quaternion(nearest_rotation(m)))) {}

  // exp(omega) = quaternion (cos(theta/2), sin(theta/2)/theta * omega),
  // theta = |omega| (Rodrigues' formula in quaternion form; Taylor series near 0).
  static SO3 exp(const Tangent& omega) {
    const auto c = lie_detail::half_angle(omega.squaredNorm());
    const Vector3 v = c.sin_half_over_theta * omega;
    return SO3(Quaternion(c.cos_half, v.x(), v.y(), v.z()), UnitTag{});
  }

  // log(R) = theta * axis with theta = 2 atan2(|v|, w) in [0, pi], after
  // choosing the quaternion sign with w >= 0. Stable near 0 (series) and near
  // pi (atan2 of a well-conditioned pair, no acos of the trace).
  Tangent log() const {
    T w = q_.w();
    Vector3 v = q_.vec();
    if (w < T(0)) {
      w = -w;
      v = -v;
    }
    return lie_detail::quaternion_log_factor(v.squaredNorm(), w) * v;
  }

  // R^-1 = R^T: the conjugate quaternion.
  SO3 inverse() const { return SO3(q_.conjugate(), UnitTag{}); }

  // Composition R_a_c = R_a_b * R_b_c (quaternion product, renormalised so
  // that long chains of products do not drift off the unit sphere).
  SO3 operator*(const SO3& other) const { return SO3(normalised(q_ * other.q_), UnitTag{}); }
  SO3& operator*=(const SO3& other) { return *this = *this * other; }

  // Rotates a point: R p.
  Vector3 operator*(const Vector3& p) const { return q_ * p; }

  // The 3x3 rotation matrix R.
  Matrix3 matrix() const { return q_.toRotationMatrix(); }

  // Adjoint: R exp(omega) R^-1 = exp(Ad(R) omega) with Ad(R) = R.
  Matrix3 adjoint() const { return matrix(); }

  const Quaternion& unit_quaternion() const { return q_; }
  // The four quaternion coefficients in Eigen's order [x, y, z, w].
  const T* data() const { return q_.coeffs().data(); }

  template <class U>
  SO3<U> cast() const {
    return SO3<U>::from_quaternion_unchecked(q_.template cast<U>());
  }

  // hat(omega) = [[0, -wz, wy], [wz, 0, -wx], [-wy, wx, 0]], so hat(a) b = a x b.
  static Matrix3 hat(const Vector3& w) {
    Matrix3 m;
    m << T(0), -w.z(), w.y(),  //
        w.z(), T(0), -w.x(),   //
        -w.y(), w.x(), T(0);
    return m;
  }

  // vee(hat(omega)) = omega (reads the lower-triangle entries).
  static Vector3 vee(const Matrix3& m) { return Vector3(m(2, 1), m(0, 2), m(1, 0)); }

  // J_l(omega) = sum_n hat^n / (n+1)! = I + B hat + C hat^2,
  // B = (1 - cos theta)/theta^2, C = (theta - sin theta)/theta^3.
  // It is also the V matrix of the SE3 exponential (t = J_l(omega) rho).
  static Matrix3 left_jacobian(const Vector3& omega) {
    const T theta_sq = omega.squaredNorm();
    const Matrix3 h = hat(omega);
    return Matrix3::Identity() + lie_detail::one_minus_cos_over_theta_sq(theta_sq) * h +
           lie_detail::theta_minus_sin_over_theta_cubed(theta_sq) * h * h;
  }

  // J_r(omega) = J_l(-omega) = I - B hat + C hat^2 (also R^T J_l(omega)).
  static Matrix3 right_jacobian(const Vector3& omega) { return left_jacobian(-omega); }

  // J_l^-1(omega) = I - hat/2 + D hat^2, D = (1 - (theta/2) cot(theta/2))/theta^2.
  // Valid for |omega| < 2 pi (always the case for the output of log()).
  static Matrix3 left_jacobian_inverse(const Vector3& omega) {
    const Matrix3 h = hat(omega);
    return Matrix3::Identity() - T(0.5) * h + lie_detail::inverse_jacobian_coefficient(omega.squaredNorm()) * h * h;
  }

  // J_r^-1(omega) = J_l^-1(-omega) = I + hat/2 + D hat^2.
  static Matrix3 right_jacobian_inverse(const Vector3& omega) { return left_jacobian_inverse(-omega); }

  // d(exp(delta) R p)/d(delta) at delta = 0: -hat(R p).
  Matrix3 left_update_point_jacobian(const Vector3& p) const { return -hat(*this * p); }

 private:
  struct UnitTag {};
  // For quaternions that are unit by construction (exp, conjugate, normalised).
  SO3(const Quaternion& q, UnitTag) : q_(q) {}

  static Quaternion normalised(const Quaternion& q) {
    using std::sqrt;
    return Quaternion(q.coeffs() / sqrt(q.squaredNorm()));
  }

  static Quaternion checked_normalised(const Quaternion& q) {
    using std::isfinite;
    const T n_sq = q.squaredNorm();
    if (!(n_sq > T(0)) || !isfinite(n_sq))
      throw std::invalid_argument("SO3: the quaternion must be non-zero and finite");
    return normalised(q);
  }

  static Matrix3 nearest_rotation(const Matrix3& m) {
    using std::isfinite;
    if (!isfinite(m.squaredNorm())) throw std::invalid_argument("SO3: the rotation matrix must be finite");
    if constexpr (!std::is_floating_point_v<T>) {
      return m;
    } else {
      const Eigen::JacobiSVD<Matrix3> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
      Matrix3 d = Matrix3::Identity();
      if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < T(0)) d(2, 2) = T(-1);
      return svd.matrixU() * d * svd.matrixV().transpose();
    }
  }

  Quaternion q_;
};

using SO3d = SO3<double>;
using SO3f = SO3<float>;

}  // namespace facadeslam
