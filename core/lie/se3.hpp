#pragma once
// SE3<T>: rigid-body transforms (rotation SO3<T> + translation), templated on
// the scalar so that Ceres can auto-differentiate through them.
//
// Conventions — every module relies on these:
//  * Pose names follow T_a_b: T_a_b maps a point from frame b to frame a,
//    p_a = T_a_b * p_b = R p_b + t. T_c_w maps world points into the camera.
//  * The tangent vector is xi = [rho, omega]: TRANSLATION PART FIRST (rho,
//    3 values), then ROTATION (omega, axis-angle, 3 values).
//  * exp(xi) = (exp(omega), J_l(omega) rho), the matrix exponential of
//    hat(xi) = [[hat(omega), rho], [0, 0]].
//  * Pose updates are LEFT-multiplicative: T_c_w <- exp(delta) * T_c_w, i.e.
//    delta is expressed in the camera (left) frame. The tracker, bundle
//    adjustment and the Ceres manifolds (core/lie/manifolds.hpp) all use
//    this; left_update_point_jacobian() gives the matching point Jacobian.
//  * Adjoint: T exp(xi) T^-1 = exp(Ad(T) xi), Ad(T) = [[R, hat(t) R], [0, R]]
//    in the [rho, omega] ordering.
#include <Eigen/Core>

#include "core/lie/so3.hpp"

namespace facadeslam {

template <class T>
class SE3 {
 public:
  using Scalar = T;
  using Vector3 = Eigen::Matrix<T, 3, 1>;
  using Vector4 = Eigen::Matrix<T, 4, 1>;
  using Matrix3 = Eigen::Matrix<T, 3, 3>;
  using Matrix4 = Eigen::Matrix<T, 4, 4>;
  using Matrix3x4 = Eigen::Matrix<T, 3, 4>;
  using Matrix6 = Eigen::Matrix<T, 6, 6>;
  using Quaternion = Eigen::Quaternion<T>;
  using Tangent = Eigen::Matrix<T, 6, 1>;  // [rho (translation), omega (rotation)]
  using PointJacobian = Eigen::Matrix<T, 3, 6>;
  static constexpr int kDof = 6;

  // The identity transform.
  SE3() : translation_(Vector3::Zero()) {}
  SE3(const SO3<T>& rotation, const Vector3& translation) : rotation_(rotation), translation_(translation) {}
  // The quaternion is normalised (see SO3).
  SE3(const Quaternion& q, const Vector3& translation) : rotation_(q), translation_(translation) {}
  // The matrix is projected onto the nearest rotation (see SO3).
  SE3(const Matrix3& r, const Vector3& translation) : rotation_(r), translation_(translation) {}
  // From a homogeneous 4x4 matrix [[R, t], [0, 1]] (the bottom row is ignored).
  explicit SE3(const Matrix4& m)
      : rotation_(Matrix3(m.template topLeftCorner<3, 3>())), translation_(m.template topRightCorner<3, 1>()) {}

  // exp([rho, omega]) = (exp(omega), V rho) with V = J_l(omega)
  //                   = I + (1 - cos theta)/theta^2 hat + (theta - sin theta)/theta^3 hat^2.
  static SE3 exp(const Tangent& xi) {
    const Vector3 rho = xi.template head<3>();
    const Vector3 omega = xi.template tail<3>();
    return SE3(SO3<T>::exp(omega), SO3<T>::left_jacobian(omega) * rho);
  }

  // log(T) = [V^-1 t, omega] with omega = log(R), |omega| <= pi,
  // V^-1 = J_l^-1(omega) = I - hat/2 + (1 - (theta/2) cot(theta/2))/theta^2 hat^2.
  Tangent log() const {
    const Vector3 omega = rotation_.log();
    Tangent xi;
    xi << SO3<T>::left_jacobian_inverse(omega) * translation_, omega;
    return xi;
  }

  // T^-1 = (R^T, -R^T t).
  SE3 inverse() const {
    const SO3<T> r_inv = rotation_.inverse();
    return SE3(r_inv, -(r_inv * translation_));
  }

  // T_a_c = T_a_b * T_b_c = (R_ab R_bc, R_ab t_bc + t_ab).
  SE3 operator*(const SE3& other) const {
    return SE3(rotation_ * other.rotation_, rotation_ * other.translation_ + translation_);
  }
  SE3& operator*=(const SE3& other) { return *this = *this * other; }

  // p_a = T_a_b * p_b = R p_b + t.
  Vector3 operator*(const Vector3& p) const { return rotation_ * p + translation_; }

  // The homogeneous 4x4 matrix [[R, t], [0, 0, 0, 1]].
  Matrix4 matrix() const {
    Matrix4 m = Matrix4::Identity();
    m.template topLeftCorner<3, 4>() = matrix3x4();
    return m;
  }

  // As an Eigen isometry (what trajectories and the renderer store).
  Eigen::Transform<T, 3, Eigen::Isometry> isometry() const {
    Eigen::Transform<T, 3, Eigen::Isometry> iso = Eigen::Transform<T, 3, Eigen::Isometry>::Identity();
    iso.linear() = rotation_.matrix();
    iso.translation() = translation_;
    return iso;
  }

  // The top three rows [R | t].
  Matrix3x4 matrix3x4() const {
    Matrix3x4 m;
    m.template leftCols<3>() = rotation_.matrix();
    m.col(3) = translation_;
    return m;
  }

  // Ad(T) = [[R, hat(t) R], [0, R]] for xi = [rho, omega]:
  // T exp(xi) T^-1 = exp(Ad(T) xi), equivalently Ad(T) xi = vee(T hat(xi) T^-1).
  Matrix6 adjoint() const {
    const Matrix3 r = rotation_.matrix();
    Matrix6 ad;
    ad.template topLeftCorner<3, 3>() = r;
    ad.template topRightCorner<3, 3>() = SO3<T>::hat(translation_) * r;
    ad.template bottomLeftCorner<3, 3>().setZero();
    ad.template bottomRightCorner<3, 3>() = r;
    return ad;
  }

  // hat([rho, omega]) = [[hat(omega), rho], [0, 0]] (4x4 Lie algebra element).
  static Matrix4 hat(const Tangent& xi) {
    Matrix4 m = Matrix4::Zero();
    m.template topLeftCorner<3, 3>() = SO3<T>::hat(xi.template tail<3>());
    m.template topRightCorner<3, 1>() = xi.template head<3>();
    return m;
  }

  // vee(hat(xi)) = xi.
  static Tangent vee(const Matrix4& m) {
    Tangent xi;
    xi << m.template topRightCorner<3, 1>(), SO3<T>::vee(m.template topLeftCorner<3, 3>());
    return xi;
  }

  // Jacobian of exp(delta) * T * p with respect to delta at delta = 0, for the
  // left-multiplicative update: [I3, -hat(T p)] (3x6, columns [rho, omega]).
  PointJacobian left_update_point_jacobian(const Vector3& p) const { return left_update_point_jacobian_at(*this * p); }

  // The same Jacobian from the already transformed point q = T p: [I3, -hat(q)].
  static PointJacobian left_update_point_jacobian_at(const Vector3& q) {
    PointJacobian j;
    j.template leftCols<3>().setIdentity();
    j.template rightCols<3>() = -SO3<T>::hat(q);
    return j;
  }

  const SO3<T>& so3() const { return rotation_; }
  const Vector3& translation() const { return translation_; }
  Vector3& translation() { return translation_; }
  void set_rotation(const SO3<T>& rotation) { rotation_ = rotation; }
  Matrix3 rotation_matrix() const { return rotation_.matrix(); }
  const Quaternion& unit_quaternion() const { return rotation_.unit_quaternion(); }

  template <class U>
  SE3<U> cast() const {
    return SE3<U>(rotation_.template cast<U>(), translation_.template cast<U>());
  }

 private:
  SO3<T> rotation_;
  Vector3 translation_;
};

using SE3d = SE3<double>;
using SE3f = SE3<float>;

}  // namespace facadeslam
