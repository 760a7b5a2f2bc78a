#pragma once
// Sim3<T>: similarity transforms p -> s R p + t (rotation, translation,
// positive scale), templated on the scalar for Ceres auto-differentiation.
// Used to align monocular trajectories (arbitrary scale) and for scale-aware
// corrections.
//
// Conventions (extending SE3's, see se3.hpp):
//  * Tangent xi = [rho (translation part, 3), omega (rotation, 3),
//    sigma (log of the scale, 1)]: 7 values in THIS order.
//  * hat(xi) = [[hat(omega) + sigma I, rho], [0, 0]] and
//    exp(xi) = (exp(omega), W rho, e^sigma) with
//    W = int_0^1 e^(sigma u) exp(u hat(omega)) du (closed form in
//    core/lie/lie_coefficients.hpp, exact in the limits theta -> 0 and sigma -> 0).
//  * Updates are left-multiplicative like SE3: S <- exp(delta) * S.
//  * Adjoint: S exp(xi) S^-1 = exp(Ad(S) xi),
//    Ad(S) = [[s R, hat(t) R, -t], [0, R, 0], [0, 0, 1]].
//  * The public constructors reject a scale that is not finite and > 0
//    (std::invalid_argument); operations never throw (an overflowing scale
//    becomes inf), and from_parts_unchecked() is the non-throwing path for
//    solver inner loops.
#include <cmath>
#include <stdexcept>

#include <Eigen/Core>
#include <Eigen/LU>

#include "core/lie/se3.hpp"
#include "core/lie/so3.hpp"

namespace facadeslam {

template <class T>
class Sim3 {
 public:
  using Scalar = T;
  using Vector3 = Eigen::Matrix<T, 3, 1>;
  using Matrix3 = Eigen::Matrix<T, 3, 3>;
  using Matrix4 = Eigen::Matrix<T, 4, 4>;
  using Matrix3x4 = Eigen::Matrix<T, 3, 4>;
  using Matrix7 = Eigen::Matrix<T, 7, 7>;
  using Quaternion = Eigen::Quaternion<T>;
  using Tangent = Eigen::Matrix<T, 7, 1>;  // [rho, omega, sigma = log(scale)]
  using PointJacobian = Eigen::Matrix<T, 3, 7>;
  static constexpr int kDof = 7;

  // The identity transform (scale 1).
  Sim3() : translation_(Vector3::Zero()), scale_(T(1)) {}
  // Throws std::invalid_argument unless scale is finite and > 0.
  Sim3(const SO3<T>& rotation, const Vector3& translation, const T& scale)
      : rotation_(rotation), translation_(translation), scale_(checked_scale(scale)) {}
  // The same without the scale check, for solver inner loops.
  static Sim3 from_parts_unchecked(const SO3<T>& rotation, const Vector3& translation, const T& scale) {
    return Sim3(rotation, translation, scale, UncheckedTag{});
  }
  // A rigid transform with a scale: p -> scale R p + t.
  Sim3(const SE3<T>& pose, const T& scale) : Sim3(pose.so3(), pose.translation(), scale) {}
  // From a homogeneous 4x4 matrix [[s R, t], [0, 1]] (e.g. Eigen::umeyama's
  // output): s = cbrt(det(s R)), R is the nearest rotation to (s R) / s.
  // Throws std::invalid_argument unless det(s R) > 0.
  explicit Sim3(const Matrix4& m) : Sim3(from_matrix(m)) {}

  // exp([rho, omega, sigma]) = (exp(omega), W(omega, sigma) rho, e^sigma),
  // W = A I + B hat(omega) + C hat(omega)^2 (see lie_detail::sim3_w_coefficients).
  static Sim3 exp(const Tangent& xi) {
    using std::exp;
    const Vector3 rho = xi.template head<3>();
    const Vector3 omega = xi.template segment<3>(3);
    const T sigma = xi(6);
    return Sim3(SO3<T>::exp(omega), w_matrix(omega, sigma) * rho, exp(sigma), UncheckedTag{});
  }

  // log(S) = [W^-1 t, log(R), log(s)], |omega| <= pi. W is invertible for
  // |omega| < 2 pi (its eigenvalues are (e^z - 1)/z, z = sigma, sigma +- i theta).
  Tangent log() const {
    using std::log;
    const Vector3 omega = rotation_.log();
    const T sigma = log(scale_);
    Tangent xi;
    xi << w_matrix(omega, sigma).inverse() * translation_, omega, sigma;
    return xi;
  }

  // S^-1 = (R^T, -R^T t / s, 1 / s).
  Sim3 inverse() const {
    const SO3<T> r_inv = rotation_.inverse();
    const T s_inv = T(1) / scale_;
    return Sim3(r_inv, -(s_inv * (r_inv * translation_)), s_inv, UncheckedTag{});
  }

  // S_a_c = S_a_b * S_b_c = (R_ab R_bc, s_ab R_ab t_bc + t_ab, s_ab s_bc).
  Sim3 operator*(const Sim3& other) const {
    return Sim3(rotation_ * other.rotation_, scale_ * (rotation_ * other.translation_) + translation_,
                scale_ * other.scale_, UncheckedTag{});
  }
  Sim3& operator*=(const Sim3& other) { return *this = *this * other; }

  // S p = s R p + t.
  Vector3 operator*(const Vector3& p) const { return scale_ * (rotation_ * p) + translation_; }

  // The homogeneous 4x4 matrix [[s R, t], [0, 0, 0, 1]].
  Matrix4 matrix() const {
    Matrix4 m = Matrix4::Identity();
    m.template topLeftCorner<3, 4>() = matrix3x4();
    return m;
  }

  // The top three rows [s R | t].
  Matrix3x4 matrix3x4() const {
    Matrix3x4 m;
    m.template leftCols<3>() = scale_ * rotation_.matrix();
    m.col(3) = translation_;
    return m;
  }

  // Ad(S) = [[s R, hat(t) R, -t], [0, R, 0], [0, 0, 1]] for [rho, omega, sigma]:
  // S hat(xi) S^-1 = [[hat(R omega) + sigma I, s R rho + t x (R omega) - sigma t], [0, 0]].
  Matrix7 adjoint() const {
    const Matrix3 r = rotation_.matrix();
    Matrix7 ad = Matrix7::Zero();
    ad.template block<3, 3>(0, 0) = scale_ * r;
    ad.template block<3, 3>(0, 3) = SO3<T>::hat(translation_) * r;
    ad.template block<3, 1>(0, 6) = -translation_;
    ad.template block<3, 3>(3, 3) = r;
    ad(6, 6) = T(1);
    return ad;
  }

  // hat([rho, omega, sigma]) = [[hat(omega) + sigma I, rho], [0, 0]].
  static Matrix4 hat(const Tangent& xi) {
    Matrix4 m = Matrix4::Zero();
    m.template topLeftCorner<3, 3>() = SO3<T>::hat(xi.template segment<3>(3)) + xi(6) * Matrix3::Identity();
    m.template topRightCorner<3, 1>() = xi.template head<3>();
    return m;
  }

  // vee(hat(xi)) = xi: sigma is a third of the trace of the top-left block,
  // omega the vee of its skew part.
  static Tangent vee(const Matrix4& m) {
    const Matrix3 a = m.template topLeftCorner<3, 3>();
    const Matrix3 skew = T(0.5) * (a - a.transpose());
    Tangent xi;
    xi << m.template topRightCorner<3, 1>(), SO3<T>::vee(skew), a.trace() / T(3);
    return xi;
  }

  // Jacobian of exp(delta) * S * p with respect to delta at delta = 0:
  // [I3, -hat(S p), S p] (3x7, columns [rho, omega, sigma]).
  PointJacobian left_update_point_jacobian(const Vector3& p) const {
    const Vector3 q = *this * p;
    PointJacobian j;
    j.template leftCols<3>().setIdentity();
    j.template middleCols<3>(3) = -SO3<T>::hat(q);
    j.col(6) = q;
    return j;
  }

  // W(omega, sigma) = int_0^1 e^(sigma u) exp(u hat(omega)) du, the matrix
  // mapping rho to the translation in exp(); equals J_l(omega) at sigma = 0.
  static Matrix3 w_matrix(const Vector3& omega, const T& sigma) {
    const auto c = lie_detail::sim3_w_coefficients(sigma, omega.squaredNorm());
    const Matrix3 h = SO3<T>::hat(omega);
    return c.a * Matrix3::Identity() + c.b * h + c.c * h * h;
  }

  const SO3<T>& so3() const { return rotation_; }
  const Vector3& translation() const { return translation_; }
  const T& scale() const { return scale_; }
  Matrix3 rotation_matrix() const { return rotation_.matrix(); }
  const Quaternion& unit_quaternion() const { return rotation_.unit_quaternion(); }
  // The rigid part (R, t), dropping the scale.
  SE3<T> se3() const { return SE3<T>(rotation_, translation_); }

  template <class U>
  Sim3<U> cast() const {
    return Sim3<U>::from_parts_unchecked(rotation_.template cast<U>(), translation_.template cast<U>(),
                                         static_cast<U>(scale_));
  }

 private:
  struct UncheckedTag {};
  Sim3(const SO3<T>& rotation, const Vector3& translation, const T& scale, UncheckedTag)
      : rotation_(rotation), translation_(translation), scale_(scale) {}

  static T checked_scale(const T& s) {
    using std::isfinite;
    if (!(s > T(0)) || !isfinite(s)) throw std::invalid_argument("Sim3: the scale must be finite and > 0");
    return s;
  }

  static Sim3 from_matrix(const Matrix4& m) {
    using std::cbrt;
    const Matrix3 sr = m.template topLeftCorner<3, 3>();
    const T det = sr.determinant();
    if (!(det > T(0))) throw std::invalid_argument("Sim3: the 3x3 block of the matrix must have det > 0");
    const T s = cbrt(det);
    return Sim3(SO3<T>(Matrix3(sr / s)), m.template topRightCorner<3, 1>(), s);
  }

  SO3<T> rotation_;
  Vector3 translation_;
  T scale_;
};

using Sim3d = Sim3<double>;
using Sim3f = Sim3<float>;

}  // namespace facadeslam
