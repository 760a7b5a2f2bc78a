#include "core/lie/manifolds.hpp"

#include <cmath>

namespace facadeslam {
namespace {

using Matrix3 = Eigen::Matrix3d;
using Vector3 = Eigen::Vector3d;
using QuaternionCoeffs = Eigen::Vector4d;  // [x, y, z, w]

// First-order change of the quaternion of exp(omega) * x: q' = q + (0, omega)/2 (x) q,
// whose derivative with respect to omega is the 4x3 matrix
// H = [w I - hat(v); -v^T] / 2 (rows x, y, z, w).
Eigen::Matrix<double, 4, 3> quaternion_left_update_jacobian(const QuaternionCoeffs& q) {
  const Vector3 v = q.head<3>();
  const double w = q(3);
  Eigen::Matrix<double, 4, 3> h;
  h.topRows<3>() = 0.5 * (w * Matrix3::Identity() - SO3d::hat(v));
  h.row(3) = -0.5 * v.transpose();
  return h;
}

// Derivative of omega = log(q_y (x) q_x^-1) with respect to q_y at q_y = q_x:
// 2 G with G = [w I + hat(v), -v] (columns x, y, z, w). G H = I / 2 for the H
// above, and G q = 0, so normalising q_y inside Minus does not change it.
Eigen::Matrix<double, 3, 4> quaternion_minus_jacobian(const QuaternionCoeffs& q) {
  const Vector3 v = q.head<3>();
  const double w = q(3);
  Eigen::Matrix<double, 3, 4> g;
  g.leftCols<3>() = 2.0 * (w * Matrix3::Identity() + SO3d::hat(v));
  g.col(3) = -2.0 * v;
  return g;
}

// The unit quaternion of a parameter block (x may carry a slightly non-unit
// quaternion; the Jacobians are those at its normalisation).
QuaternionCoeffs unit_quaternion_of(const double* x) { return Eigen::Map<const QuaternionCoeffs>(x).normalized(); }

// A block Plus/Minus can work with: finite values and a non-zero quaternion.
bool valid_block(const double* x, int size) {
  for (int i = 0; i < size; ++i)
    if (!std::isfinite(x[i])) return false;
  return Eigen::Map<const QuaternionCoeffs>(x).squaredNorm() > 0.0;
}

bool all_finite(const double* v, int size) {
  for (int i = 0; i < size; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

}  // namespace

bool SE3Manifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  if (!valid_block(x, kSe3ParamSize) || !all_finite(delta, SE3d::kDof)) return false;
  const SE3d pose = SE3d::exp(Eigen::Map<const SE3d::Tangent>(delta)) * se3_from_params(x);
  se3_to_params(pose, x_plus_delta);
  return true;
}

bool SE3Manifold::PlusJacobian(const double* x, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, 7, 6, Eigen::RowMajor>> j(jacobian);
  const Vector3 t(x[4], x[5], x[6]);
  j.setZero();
  j.block<4, 3>(0, 3) = quaternion_left_update_jacobian(unit_quaternion_of(x));
  j.block<3, 3>(4, 0).setIdentity();
  j.block<3, 3>(4, 3) = -SO3d::hat(t);
  return true;
}

bool SE3Manifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  if (!valid_block(x, kSe3ParamSize) || !valid_block(y, kSe3ParamSize)) return false;
  Eigen::Map<SE3d::Tangent> out(y_minus_x);
  out = (se3_from_params(y) * se3_from_params(x).inverse()).log();
  return true;
}

bool SE3Manifold::MinusJacobian(const double* x, double* jacobian) const {
  // At y = x: omega ~= 2 vec(q_y q_x^-1), rho ~= t_y - R_y R_x^T t_x ~= t_y - t_x + hat(t_x) omega.
  Eigen::Map<Eigen::Matrix<double, 6, 7, Eigen::RowMajor>> j(jacobian);
  const Vector3 t(x[4], x[5], x[6]);
  const Eigen::Matrix<double, 3, 4> g2 = quaternion_minus_jacobian(unit_quaternion_of(x));
  j.setZero();
  j.block<3, 4>(0, 0) = SO3d::hat(t) * g2;
  j.block<3, 3>(0, 4).setIdentity();
  j.block<3, 4>(3, 0) = g2;
  return true;
}

bool Sim3Manifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  if (!valid_block(x, kSim3ParamSize) || !all_finite(delta, Sim3d::kDof)) return false;
  const Sim3d s = Sim3d::exp(Eigen::Map<const Sim3d::Tangent>(delta)) * sim3_from_params(x);
  se3_to_params(s.se3(), x_plus_delta);
  // log(s_delta * s_x) = sigma + log_scale_x, written additively rather than
  // through exp/log: no round-off, and no overflow for a huge sigma.
  x_plus_delta[7] = delta[6] + x[7];
  return true;
}

bool Sim3Manifold::PlusJacobian(const double* x, double* jacobian) const {
  Eigen::Map<Eigen::Matrix<double, 8, 7, Eigen::RowMajor>> j(jacobian);
  const Vector3 t(x[4], x[5], x[6]);
  j.setZero();
  j.block<4, 3>(0, 3) = quaternion_left_update_jacobian(unit_quaternion_of(x));
  j.block<3, 3>(4, 0).setIdentity();
  j.block<3, 3>(4, 3) = -SO3d::hat(t);
  j.block<3, 1>(4, 6) = t;
  j(7, 6) = 1.0;
  return true;
}

bool Sim3Manifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  if (!valid_block(x, kSim3ParamSize) || !valid_block(y, kSim3ParamSize)) return false;
  // Relative transform y x^-1 with its log-scale taken additively (exact, and
  // free of overflow for large scales), then the SE3-like part of the log.
  // y x^-1 = (R_y R_x^T, t_y - e^sigma R_y R_x^T t_x, e^sigma).
  const double sigma = y[7] - x[7];
  const SO3d rotation = se3_from_params(y).so3() * se3_from_params(x).so3().inverse();
  const Vector3 translation = Vector3(y[4], y[5], y[6]) - std::exp(sigma) * (rotation * Vector3(x[4], x[5], x[6]));
  const Vector3 omega = rotation.log();
  Eigen::Map<Sim3d::Tangent> out(y_minus_x);
  out << Sim3d::w_matrix(omega, sigma).inverse() * translation, omega, sigma;
  return true;
}

bool Sim3Manifold::MinusJacobian(const double* x, double* jacobian) const {
  // At y = x: sigma = ls_y - ls_x, omega ~= 2 vec(q_y q_x^-1),
  // rho ~= t_y - (1 + sigma) R_y R_x^T t_x ~= t_y - t_x + hat(t_x) omega - sigma t_x.
  Eigen::Map<Eigen::Matrix<double, 7, 8, Eigen::RowMajor>> j(jacobian);
  const Vector3 t(x[4], x[5], x[6]);
  const Eigen::Matrix<double, 3, 4> g2 = quaternion_minus_jacobian(unit_quaternion_of(x));
  j.setZero();
  j.block<3, 4>(0, 0) = SO3d::hat(t) * g2;
  j.block<3, 3>(0, 4).setIdentity();
  j.block<3, 1>(0, 7) = -t;
  j.block<3, 4>(3, 0) = g2;
  j(6, 7) = 1.0;
  return true;
}

}  // namespace facadeslam
